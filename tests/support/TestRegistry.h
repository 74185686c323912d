#pragma once
// The test groups' registry (TestMain.h, TestGroupMain.cpp): a test file's runner under its
// file's name.

namespace stepdeck::test {

using TestRunner = int (*)(int argc, char** argv);

// Registers `run` under the base name of `sourceFile` (tst_programlexer.cpp: tst_programlexer).
// Returns true; a second file of the same name is reported by the group's main.
bool registerTest(const char* sourceFile, TestRunner run);

} // namespace stepdeck::test
