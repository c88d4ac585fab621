# SPDX-License-Identifier: MIT
# Live input: the streaming planner per pushed note (lookahead 0, 3, 6) and the live pianist's
# update per note (fingering + contacts + a new motion).
add_executable(live_input_benchmark live_input_benchmark.cpp)
target_link_libraries(live_input_benchmark PRIVATE tutti::live tutti::fingering_planner
                      tutti::music tutti_warnings benchmark::benchmark_main)
target_compile_definitions(live_input_benchmark PRIVATE
                           TUTTI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
