// SPDX-License-Identifier: MIT
// The header check's precompiled header (tests/package/CMakeLists.txt): the standard and GLM
// headers that the public headers use most, parsed once instead of once per header. The check no
// longer sees a header that forgets one of these, so std_includes_test.py checks exactly these by
// name, and fails on a header here that it does not check.
#include <algorithm>
#include <any>
#include <array>
#include <atomic>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
