# Main window: fits ordinary screens (issue 11).
stepdeck_add_test(tst_windowfit SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_windowfit.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_add_test(tst_statusmessages SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_statusmessages.cpp
                  LABELS unit LIBS stepdeck_ui)
