stepdeck_add_test(tst_jogramp SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jogramp.cpp LABELS unit)
stepdeck_add_test(tst_statuspoller SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_statuspoller.cpp LABELS unit)
stepdeck_add_test(tst_controllerbase SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_controllerbase.cpp LABELS unit)
stepdeck_add_test(tst_softlimits SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_softlimits.cpp LABELS unit)
