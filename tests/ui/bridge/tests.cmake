# The Laser bridge page against the in-process E-LAB simulator and a scripted laser on a pty.
stepdeck_add_test(tst_laserbridgepage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laserbridgepage.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
