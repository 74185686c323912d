# Shared dialog helpers: file dialogs remember the last folder (issue 11).
stepdeck_add_test(tst_dialogs SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_dialogs.cpp
                  LABELS ui LIBS stepdeck_ui)
# Setters that skip an unchanged value (issue 21, idle cost).
stepdeck_add_test(tst_ifchanged SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_ifchanged.cpp
                  LABELS ui LIBS stepdeck_ui)
