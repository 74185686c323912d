stepdeck_add_test(tst_elabcodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_elabcodec.cpp LABELS unit)
