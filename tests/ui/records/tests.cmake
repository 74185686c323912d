# The records / error-memory page (Nanotec) against the in-process simulator.
stepdeck_add_test(tst_recordspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_recordspage.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h LABELS ui LIBS stepdeck_ui)
