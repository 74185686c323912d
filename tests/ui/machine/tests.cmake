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
