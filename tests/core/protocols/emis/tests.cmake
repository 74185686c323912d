stepdeck_add_test(tst_emiscodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_emiscodec.cpp LABELS unit)
stepdeck_add_test(tst_emisgrammar SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_emisgrammar.cpp LABELS unit)
stepdeck_add_test(tst_emissimulator SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_emissimulator.cpp LABELS unit)
