// SPDX-License-Identifier: MIT
#include <tutti/editor/json_edit.hpp>

#include <gtest/gtest.h>

namespace tutti::editor {
namespace {

Json document() { return Json::parse(R"({"b": 1, "a": {"list": [1, 2, 3]}, "c": "x"})"); }

TEST(JsonEdit, ReplaceInsertEraseAndUndoExactly) {
  Json doc = document();
  const std::string original = doc.dump();
  Edit edit;
  edit.label = "three changes";
  edit.changes.push_back({"/b", Json(1), Json(2)});                // replace
  edit.changes.push_back({"/a/list/1", std::nullopt, Json(9)});    // insert in an array
  edit.changes.push_back({"/c", Json("x"), std::nullopt});         // remove a key
  edit.changes.push_back({"/d", std::nullopt, Json::array({4})});  // add a key
  ASSERT_TRUE(apply_edit(doc, edit));
  EXPECT_EQ(doc.dump(), R"({"b":2,"a":{"list":[1,9,2,3]},"d":[4]})") << "key order kept";
  ASSERT_TRUE(revert_edit(doc, edit));
  EXPECT_TRUE(same_json(doc, Json::parse(original)));
  EXPECT_EQ(doc["a"]["list"], Json::parse("[1, 2, 3]"));
}

TEST(JsonEdit, AStaleEditChangesNothing) {
  Json doc = document();
  Edit edit;
  edit.changes.push_back({"/b", Json(1), Json(5)});
  edit.changes.push_back({"/a/list/0", Json(7), Json(8)});  // the document has 1 there
  const Status s = apply_edit(doc, edit);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().message,
            "edit at /a/list/0: the document no longer has what the edit expects there");
  EXPECT_EQ(doc, document()) << "all or nothing";
  Edit missing_parent;
  missing_parent.changes.push_back({"/nope/x", std::nullopt, Json(1)});
  EXPECT_EQ(apply_edit(doc, missing_parent).error().message,
            "edit at /nope/x: its parent does not exist");
  Edit out_of_range;
  out_of_range.changes.push_back({"/a/list/7", std::nullopt, Json(1)});
  EXPECT_EQ(apply_edit(doc, out_of_range).error().message,
            "edit at /a/list/7: array index out of range");
}

TEST(JsonEdit, SameJsonIgnoresKeyOrder) {
  EXPECT_TRUE(same_json(Json::parse(R"({"a": 1, "b": 2})"), Json::parse(R"({"b": 2, "a": 1})")));
  EXPECT_FALSE(same_json(Json::parse(R"({"a": 1})"), Json::parse(R"({"a": 2})")));
}

}  // namespace
}  // namespace tutti::editor
