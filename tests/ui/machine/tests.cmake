# The machine editor and the File menu's machine actions (issue 19).
stepdeck_add_test(tst_machineeditor SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineeditor.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_test_definitions(tst_machineeditor STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
stepdeck_add_test(tst_machineeditorfiles SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineeditorfiles.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_test_definitions(tst_machineeditorfiles STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
stepdeck_add_test(tst_machinefileactions SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinefileactions.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_test_definitions(tst_machinefileactions STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The main window running a machine of several controllers (issue 19, ui/machine/): an E-LAB
# and a Nanotec simulator on two pseudo-terminals (MachineWindowRig), on a 1366x768 screen.
foreach(_test tst_machinewindow tst_machinesafety tst_machineposition tst_machinejog
              tst_machinereopen tst_machinegotoaxes)
  stepdeck_add_test(${_test} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_test}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/MachineWindowRig.h ${CMAKE_CURRENT_LIST_DIR}/../LaptopScreen.h
                    ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                    ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                    LABELS ui LIBS stepdeck_ui)
endforeach()
# Re-open machine edits through the editor (MachineEditorTestSupport.h names the examples).
stepdeck_test_definitions(tst_machinereopen STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The machine's read-out and go-to on the connection bar's controller (issue 28, item 0),
# against the in-process simulator.
foreach(_test tst_machinedro tst_machinegoto tst_machinecontrol)
  stepdeck_add_test(${_test} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_test}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                    LABELS ui LIBS stepdeck_ui)
endforeach()
# The read-out's estimate of a positioning move without position read-back (pure).
stepdeck_add_test(tst_moveestimate SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_moveestimate.cpp
                  LABELS unit LIBS stepdeck_ui)
# The machine's tool table: kept per machine, edited as LinuxCNC tool.tbl text (issue 29).
stepdeck_add_test(tst_tooltabledialog SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_tooltabledialog.cpp
                  LABELS ui LIBS stepdeck_ui)
# The spindle and coolant bar on a laser machine (issue 50 item 5), at the in-process E-LAB.
stepdeck_add_test(tst_spindlecoolantbar SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_spindlecoolantbar.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h LABELS ui LIBS stepdeck_ui)
