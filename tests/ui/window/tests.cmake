# The main window (ui/window/).
# Main window: fits ordinary screens (issue 11).
stepdeck_add_test(tst_windowfit SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_windowfit.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 16: on a 1366x768 screen a long message moves nothing, the window stays on the screen,
# and safety texts, DRO rows and status lamps show in full (every model, English and German).
# 300 s: every model's parameters are read back after each connect before the long message
# (about 80 s under the sanitizers before that wait, near the default 120).
stepdeck_add_test(tst_layoutholdsstill SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_layoutholdsstill.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
                  LABELS ui LIBS stepdeck_ui TIMEOUT 300)
# Issue 16: a window whose layout minimum grows stays on its screen.
stepdeck_add_test(tst_screenbound SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_screenbound.cpp
                  LABELS ui LIBS stepdeck_ui)
# Issue 28: the Simulator menu sets the inputs the simulated machine drives.
stepdeck_add_test(tst_simulatormenu SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatormenu.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../EmisUiFixture.h

                  LABELS ui LIBS stepdeck_ui)
# Issue 31 (safety): the click that closes a menu does not reach the window under it.
stepdeck_add_test(tst_menuclickthrough SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_menuclickthrough.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 31 (a finding): Help lists the keyboard shortcuts and the command line's usage.
stepdeck_add_test(tst_helpmenu SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_helpmenu.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 31: the Run and Setup workspaces on a 1366x768 screen with a machine of two controllers
# on pseudo-terminals, and the Run workspace's fit on a 1920x1080 screen. Issue 47 item 13: the
# Program dock's separator moves (the toolpath half the workspace's height), and a maximised
# Full HD window's Setup workspace names no page as scrolling.
set(_workspaces_sources ${CMAKE_CURRENT_LIST_DIR}/tst_workspaces.cpp
    ${CMAKE_CURRENT_LIST_DIR}/../machine/MachineWindowRig.h
    ${CMAKE_CURRENT_LIST_DIR}/../LaptopScreen.h ${CMAKE_CURRENT_LIST_DIR}/../LayoutChecks.h
    ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h
    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h)
stepdeck_add_test(tst_workspaces SOURCES ${_workspaces_sources} LABELS ui LIBS stepdeck_ui)
stepdeck_add_test(tst_workspaces_fullhd STANDALONE SOURCES ${_workspaces_sources} LABELS ui
                  LIBS stepdeck_ui
                  SPLIT run_onTheScreen_noScrollBarNoTextCut
                        setup_fullHdMaximised_noPageSaidToScroll)
stepdeck_test_definitions(tst_workspaces_fullhd STEPDECK_FULL_HD)
# Issue 31: the built-in demo that tools/run opens.
stepdeck_add_test(tst_demomachine SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_demomachine.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Issue 47, item 6 (safety): the keys of actions that move the machine or change its link do
# not fire from a text field (program editor, MDI line, a form); STOP and PANIC still do.
stepdeck_add_test(tst_machineshortcuts SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineshortcuts.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
