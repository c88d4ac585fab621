# SPDX-License-Identifier: MIT
# The onset detector tutti sync-report listens with, on 10 s of a four-voice texture.
add_executable(onset_detection_benchmark onset_detection_benchmark.cpp)
target_link_libraries(onset_detection_benchmark PRIVATE tutti::audio tutti_warnings
                      benchmark::benchmark_main)
