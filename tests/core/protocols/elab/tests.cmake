stepdeck_add_test(tst_elabcodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_elabcodec.cpp LABELS unit)
stepdeck_add_test(tst_elabsimaxis SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_elabsimaxis.cpp LABELS unit)
stepdeck_add_test(tst_elabsimstream SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_elabsimstream.cpp LABELS unit)
stepdeck_add_test(tst_elabsimulator SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_elabsimulator.cpp LABELS unit)
