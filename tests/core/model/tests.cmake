stepdeck_add_test(tst_parameterschema SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_parameterschema.cpp LABELS unit)
stepdeck_add_test(tst_machinestatus SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machinestatus.cpp LABELS unit)
stepdeck_add_test(tst_numberparsing SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_numberparsing.cpp LABELS unit)
stepdeck_add_test(tst_parameterfile SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_parameterfile.cpp LABELS unit)
