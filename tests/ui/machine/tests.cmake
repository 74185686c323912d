# The machine editor and the File menu's machine actions (issue 19).
stepdeck_add_test(tst_machineeditor SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineeditor.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
target_compile_definitions(tst_machineeditor PRIVATE STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
stepdeck_add_test(tst_machineeditorfiles SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineeditorfiles.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
target_compile_definitions(tst_machineeditorfiles PRIVATE STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
stepdeck_add_test(tst_machinefileactions SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinefileactions.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MachineEditorTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
target_compile_definitions(tst_machinefileactions PRIVATE STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The main window running a machine of several controllers (issue 19, ui/machine/): an E-LAB
# and a Nanotec simulator on two pseudo-terminals.
stepdeck_add_test(tst_machinewindow SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinewindow.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                  LABELS ui LIBS stepdeck_ui)
# The jog panel jogs a machine's named axes in their units (issue 19).
stepdeck_add_test(tst_machinejog SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinejog.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# The work offsets of a machine's axes in their units (pure: store, conversion, persistence).
stepdeck_add_test(tst_machineworkoffsets SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineworkoffsets.cpp
                  LABELS unit LIBS stepdeck_ui)
