# The Program page's widgets (issue 20, ui/program/): the editor's marks, the files, the
# times, without a machine.
stepdeck_add_test(tst_programwidgets SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programwidgets.cpp
                  LABELS ui LIBS stepdeck_ui)
# The page in the main window running programs on a machine of two simulated controllers on
# pseudo-terminals (MachineWindowRig), on a 1366x768 screen; the MDI line and the check's error
# list (issue 31) likewise.
foreach(_t tst_programpage tst_programpagerun tst_mdiline tst_programerrors)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/ProgramPageFixture.h
                    ${CMAKE_CURRENT_LIST_DIR}/../machine/MachineWindowRig.h
                    ${CMAKE_CURRENT_LIST_DIR}/../LaptopScreen.h
                    ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h

                    ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                    LABELS ui LIBS stepdeck_ui TIMEOUT 300)
endforeach()
# (300 s: tst_programpagerun runs about 50 s plain and passed 120 s under ASan+UBSan beside a
# build, its 21 functions all passing.)
# A program too large to edit (issue 29): the excerpt, the check's progress and Cancel, the run
# read from the file, a file changed after its check.
stepdeck_add_test(tst_programpagelarge SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programpagelarge.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../machine/MachineWindowRig.h
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui TIMEOUT 300)
# The preview's path (issue 29): the views' projections, the zoom and pan arithmetic, the scene
# drawn from a preview, and the widget with its mouse, keys, colours and remembered view.
foreach(_t tst_programpreviewprojection tst_programpreviewviewport tst_programpreviewscene)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/PreviewTestData.h LABELS unit LIBS stepdeck_ui)
endforeach()
foreach(_t tst_programpathview tst_programpathvieworbit)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/PathViewTestSupport.h
                    ${CMAKE_CURRENT_LIST_DIR}/PreviewTestData.h LABELS ui LIBS stepdeck_ui)
endforeach()
