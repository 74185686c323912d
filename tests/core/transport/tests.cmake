stepdeck_add_test(tst_loopbacktransport SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_loopbacktransport.cpp LABELS unit)
stepdeck_add_test(tst_serialtransport SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_serialtransport.cpp LABELS integration)
stepdeck_add_test(tst_tcptransport SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_tcptransport.cpp LABELS unit)
stepdeck_add_test(tst_serialportaccess SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_serialportaccess.cpp LABELS unit)
