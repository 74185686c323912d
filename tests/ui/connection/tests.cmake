# Connecting to a controller (ui/connection/).
stepdeck_add_test(tst_connectionbar SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_connectionbar.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Auto-reconnect's device matching and the port scan off the GUI thread (issue 10).
stepdeck_add_test(tst_portwatcher SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_portwatcher.cpp
                  LABELS unit LIBS stepdeck_ui)
# Connection settings: reset line, recent ports, restore at start, auto-reconnect (issues 7, 10).
stepdeck_add_test(tst_connectionsettings SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_connectionsettings.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
