stepdeck_add_test(tst_lasercodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_lasercodec.cpp LABELS unit)
