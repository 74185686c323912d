stepdeck_add_test(tst_cliarguments SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cliarguments.cpp
  LIBS stepdeck_cli LABELS unit)
