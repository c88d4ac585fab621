// SPDX-License-Identifier: MIT
// The executable that builds the tests' precompiled header (tests/CMakeLists.txt): it has no
// tests of its own.
int main() { return 0; }
