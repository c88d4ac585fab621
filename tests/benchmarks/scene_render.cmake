# SPDX-License-Identifier: MIT
# ms per frame of the demo scenes at 1280x720 (README figures): pose, render, render + encode.
add_executable(scene_render_benchmark scene_render_benchmark.cpp)
target_link_libraries(scene_render_benchmark PRIVATE tutti::app tutti::stage tutti::render
                      tutti_warnings benchmark::benchmark_main)
target_compile_definitions(scene_render_benchmark PRIVATE TUTTI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(scene_render_benchmark tutti_content_assets)
