# SPDX-License-Identifier: MIT
# export: baking and writing a staged scene as glTF (tutti export), and the keyframe reduction.
add_executable(export_benchmark ${CMAKE_CURRENT_LIST_DIR}/export_benchmark.cpp)
target_link_libraries(export_benchmark PRIVATE tutti::export tutti::performance tutti::scene tutti_warnings
                      benchmark::benchmark_main)
target_compile_definitions(export_benchmark PRIVATE TUTTI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(export_benchmark tutti_content_assets)
