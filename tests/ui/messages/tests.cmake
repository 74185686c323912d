# The status messages, the message line and its log (ui/messages/).
stepdeck_add_test(tst_statusmessages SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_statusmessages.cpp
                  LABELS unit LIBS stepdeck_ui)
# Issue 16: the one-line message line (elided, tooltip, re-elided on resize) and the log.
stepdeck_add_test(tst_messageline SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_messageline.cpp
                  LABELS unit LIBS stepdeck_ui)
