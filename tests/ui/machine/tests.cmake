# The main window running a machine of several controllers (issue 19, ui/machine/): an E-LAB
# and a Nanotec simulator on two pseudo-terminals.
stepdeck_add_test(tst_machinewindow SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinewindow.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/PtyDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                  LABELS ui LIBS stepdeck_ui)
