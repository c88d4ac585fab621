# SPDX-License-Identifier: MIT
# Ensemble body motion: planning a player and evaluating their pose at a frame.
add_executable(ensemble_variation_benchmark ensemble_variation_benchmark.cpp)
target_link_libraries(ensemble_variation_benchmark PRIVATE tutti::ensemble_variation tutti_warnings
                      benchmark::benchmark_main)
