stepdeck_add_test(tst_simulatorfaults SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simulatorfaults.cpp LABELS unit)
