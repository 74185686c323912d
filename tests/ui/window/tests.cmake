# The main window (ui/window/).
# Main window: fits ordinary screens (issue 11).
stepdeck_add_test(tst_windowfit SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_windowfit.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 16: on a 1366x768 screen a long message moves nothing, the window stays on the screen,
# and safety texts, DRO rows and status lamps show in full (every model, English and German).
stepdeck_add_test(tst_layoutholdsstill SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_layoutholdsstill.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                  ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 16: a window whose layout minimum grows stays on its screen.
stepdeck_add_test(tst_screenbound SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_screenbound.cpp
                  LABELS ui LIBS stepdeck_ui)
# Issue 28: the Simulator menu sets the inputs the simulated machine drives.
stepdeck_add_test(tst_simulatormenu SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatormenu.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../EmisUiFixture.h
                  ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 31 (safety): the click that closes a menu does not reach the window under it.
stepdeck_add_test(tst_menuclickthrough SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_menuclickthrough.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 31 (a finding): Help lists the keyboard shortcuts and the command line's usage.
stepdeck_add_test(tst_helpmenu SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_helpmenu.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
