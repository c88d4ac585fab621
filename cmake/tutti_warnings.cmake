# SPDX-License-Identifier: MIT
# Warnings are errors in our own code; third-party headers come in as SYSTEM includes.
add_library(tutti_warnings INTERFACE)
target_compile_options(tutti_warnings INTERFACE -Wall -Wextra -Wpedantic -Werror
                       -Wshadow -Wconversion -Wno-sign-conversion)
