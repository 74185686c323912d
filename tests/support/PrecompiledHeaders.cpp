// The holder of the tests' precompiled headers (tests/CMakeLists.txt): CMake builds a
// target's precompiled header with its objects, and the tests reuse it.
