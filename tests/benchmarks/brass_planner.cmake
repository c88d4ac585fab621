# SPDX-License-Identifier: MIT
# Brass fingering planner throughput (notes per second, one core) and brass pose evaluation.
add_executable(brass_planner_benchmark brass_planner_benchmark.cpp)
target_link_libraries(brass_planner_benchmark PRIVATE tutti::brass_planner tutti::brass_motion tutti_warnings
                      benchmark::benchmark_main)
