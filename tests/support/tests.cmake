# The test files themselves (issue 48): no file-scope class or inline function defined in two of
# them, which a test group's program would silently share.
stepdeck_add_test(tst_testsourcenames SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_testsourcenames.cpp
                  LABELS unit)
stepdeck_test_definitions(tst_testsourcenames STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
