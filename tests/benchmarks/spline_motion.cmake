# SPDX-License-Identifier: MIT
# spline-motion: hand path planning throughput and evaluate() cost.
add_executable(hand_path_benchmark ${CMAKE_CURRENT_LIST_DIR}/hand_path_benchmark.cpp)
target_link_libraries(hand_path_benchmark PRIVATE tutti::spline_motion tutti_warnings benchmark::benchmark_main)
