# The main window on an EMIS SMC-IC4 (in-process simulator).
stepdeck_add_test(tst_emismainwindow SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_emismainwindow.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../EmisUiFixture.h
                  LABELS ui LIBS stepdeck_ui)
stepdeck_test_includes(tst_emismainwindow ${CMAKE_CURRENT_LIST_DIR}/..)
