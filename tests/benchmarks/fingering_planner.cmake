# SPDX-License-Identifier: MIT
# Exact fingering planner throughput (notes per second, one core).
add_executable(fingering_planner_benchmark fingering_planner_benchmark.cpp)
target_link_libraries(fingering_planner_benchmark PRIVATE tutti::fingering_planner tutti_warnings
                      benchmark::benchmark_main)
target_compile_definitions(fingering_planner_benchmark PRIVATE
                           TUTTI_CONTENT_DIR="${PROJECT_SOURCE_DIR}/content")
