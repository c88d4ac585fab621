# SPDX-License-Identifier: MIT
# key-action: the cost of sounding a piece from the motion (strokes + finger motion + keys).
add_executable(key_action_benchmark ${CMAKE_CURRENT_LIST_DIR}/key_action_benchmark.cpp)
target_link_libraries(key_action_benchmark PRIVATE tutti::key_action tutti::piano_performance
                      tutti::music tutti_warnings benchmark::benchmark_main)
target_compile_definitions(key_action_benchmark PRIVATE
                           TUTTI_CONTENT_DIR="${PROJECT_SOURCE_DIR}/content"
                           TUTTI_TESTDATA_DIR="${TUTTI_TESTDATA_DIR}")
