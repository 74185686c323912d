# The input-program editor (EMIS SMC-IC4) against the in-process simulator.
stepdeck_add_test(tst_inputprogramspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_inputprogramspage.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../EmisUiFixture.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_test_includes(tst_inputprogramspage ${CMAKE_CURRENT_LIST_DIR}/..)
