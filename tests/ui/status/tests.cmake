# The status page's list of many axes (issue 32, step 5) against the in-process Nanotec bus.
stepdeck_add_test(tst_axisstatuslist SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_axisstatuslist.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h
                  LABELS ui LIBS stepdeck_ui TIMEOUT 240)
