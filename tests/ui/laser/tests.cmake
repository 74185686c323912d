# The main window on laser motor axes (issue 16): their units, a link without polls, jogging
# by targets, a setup page without parameters.
stepdeck_add_test(tst_laserui SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserui.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
