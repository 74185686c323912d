# Main window: fits ordinary screens (issue 11).
stepdeck_add_test(tst_windowfit SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_windowfit.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_add_test(tst_statusmessages SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_statusmessages.cpp
                  LABELS unit LIBS stepdeck_ui)
# Auto-reconnect's device matching and the port scan off the GUI thread (issue 10).
stepdeck_add_test(tst_portwatcher SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_portwatcher.cpp
                  LABELS unit LIBS stepdeck_ui)
# Connection settings: reset line, recent ports, restore at start, auto-reconnect (issues 7, 10).
stepdeck_add_test(tst_connectionsettings SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_connectionsettings.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 16: on a 1366x768 screen a long message moves nothing, the window stays on the screen,
# and safety texts, DRO rows and status lamps show in full (every model, English and German).
stepdeck_add_test(tst_layoutholdsstill SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_layoutholdsstill.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                  ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 16: the one-line message line (elided, tooltip, re-elided on resize) and the log.
stepdeck_add_test(tst_messageline SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_messageline.cpp
                  LABELS unit LIBS stepdeck_ui)
# Issue 16: a window whose layout minimum grows stays on its screen.
stepdeck_add_test(tst_screenbound SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_screenbound.cpp
                  LABELS ui LIBS stepdeck_ui)
# STOP feedback at device standstill, refusals that end with their cause (issue 16).
stepdeck_add_test(tst_stopfeedback SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_stopfeedback.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
