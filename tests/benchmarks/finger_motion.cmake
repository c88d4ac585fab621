# SPDX-License-Identifier: MIT
# finger-motion: evaluate_hand_pose cost per call.
add_executable(finger_pose_benchmark ${CMAKE_CURRENT_LIST_DIR}/finger_pose_benchmark.cpp)
target_link_libraries(finger_pose_benchmark PRIVATE tutti::finger_motion tutti_warnings
                      benchmark::benchmark_main)
target_compile_definitions(finger_pose_benchmark PRIVATE
                           TUTTI_CONTENT_DIR="${PROJECT_SOURCE_DIR}/content")
