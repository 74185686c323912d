# resources/: desktop entry and metainfo validated (skips without the validators).
stepdeck_add_test(tst_desktopintegration
                  SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_desktopintegration.cpp LABELS unit)
stepdeck_test_definitions(tst_desktopintegration STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
