#pragma once
// A test file's entry point (issue 48). Each Qt Test class ends its file with one of
//   STEPDECK_TEST_MAIN(TestX)           as QTEST_MAIN (QApplication where the test links
//                                       Qt Widgets, else QGuiApplication or QCoreApplication)
//   STEPDECK_TEST_GUILESS_MAIN(TestX)   as QTEST_GUILESS_MAIN
//   STEPDECK_TEST_APPLESS_MAIN(TestX)   as QTEST_APPLESS_MAIN
//   STEPDECK_TEST_MAIN_WITH(TestX, fn)  int fn(int argc, char** argv) runs it (a screen of its own)
//
// Built on its own (STEPDECK_TEST_GROUPED undefined), each is Qt's macro: the file is a test
// program. In a test group (tests/CMakeLists.txt: the test files of a directory in one program,
// compiled a few at a time as one translation unit) each registers its class under its file's
// name instead, and the group's main (TestGroupMain.cpp) runs the one its first argument names:
// `tests_core_program tst_programlexer [Qt Test arguments]`. The test itself runs as before.
#include <QtTest>

#ifdef STEPDECK_TEST_GROUPED

#include "TestRegistry.h"

// The runner is a lambda without captures (a function pointer), one per test file; the
// registration is a file-scope constant whose name the class name makes distinct.
#define STEPDECK_TEST_REGISTER(TestObject, body)                                                   \
    static const bool stepdeckTestRegistered_##TestObject =                                        \
        stepdeck::test::registerTest(__FILE__, [](int argc, char** argv) -> int body)

// QTEST_MAIN's choice of application (qtest.h).
#if defined(QT_WIDGETS_LIB)
#define STEPDECK_TEST_GUI_APPLICATION QApplication
#elif defined(QT_GUI_LIB)
#define STEPDECK_TEST_GUI_APPLICATION QGuiApplication
#endif

#ifdef STEPDECK_TEST_GUI_APPLICATION
#define STEPDECK_TEST_MAIN(TestObject)                                                             \
    STEPDECK_TEST_REGISTER(TestObject, {                                                           \
        STEPDECK_TEST_GUI_APPLICATION app(argc, argv);                                             \
        app.setAttribute(Qt::AA_Use96Dpi, true);                                                   \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    });
#else
#define STEPDECK_TEST_MAIN(TestObject) STEPDECK_TEST_GUILESS_MAIN(TestObject)
#endif

#define STEPDECK_TEST_GUILESS_MAIN(TestObject)                                                     \
    STEPDECK_TEST_REGISTER(TestObject, {                                                           \
        QCoreApplication app(argc, argv);                                                          \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    });

#define STEPDECK_TEST_APPLESS_MAIN(TestObject)                                                     \
    STEPDECK_TEST_REGISTER(TestObject, {                                                           \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    });

#define STEPDECK_TEST_MAIN_WITH(TestObject, runner)                                                \
    STEPDECK_TEST_REGISTER(TestObject, { return runner(argc, argv); });

#else // a test program of its own

#define STEPDECK_TEST_MAIN(TestObject) QTEST_MAIN(TestObject)
#define STEPDECK_TEST_GUILESS_MAIN(TestObject) QTEST_GUILESS_MAIN(TestObject)
#define STEPDECK_TEST_APPLESS_MAIN(TestObject) QTEST_APPLESS_MAIN(TestObject)
#define STEPDECK_TEST_MAIN_WITH(TestObject, runner)                                                \
    int main(int argc, char** argv)                                                                \
    {                                                                                              \
        return runner(argc, argv);                                                                 \
    }

#endif
