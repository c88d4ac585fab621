# SPDX-License-Identifier: MIT
# editor: the cost of an edit (re-plan + undo).
add_executable(editor_replan_benchmark editor_replan_benchmark.cpp)
target_link_libraries(editor_replan_benchmark PRIVATE tutti::editor_core tutti_warnings
                      benchmark::benchmark_main)
target_compile_definitions(editor_replan_benchmark PRIVATE TUTTI_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_dependencies(editor_replan_benchmark tutti_content_assets)
