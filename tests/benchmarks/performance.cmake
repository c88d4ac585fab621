# SPDX-License-Identifier: MIT
# performance: sample(t) per frame and opening a scene (tutti::performance, docs/embedding.md).
add_executable(performance_benchmark ${CMAKE_CURRENT_LIST_DIR}/performance_benchmark.cpp)
target_link_libraries(performance_benchmark PRIVATE tutti::performance tutti_warnings
                      benchmark::benchmark_main)
target_compile_definitions(performance_benchmark PRIVATE TUTTI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(performance_benchmark tutti_content_assets)
