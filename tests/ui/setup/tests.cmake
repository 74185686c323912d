# Setup page on a Nanotec bus (read-back, unknown values, preview) against the bus simulator.
stepdeck_add_test(tst_nanotecsetup SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecsetup.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h
                  LABELS ui LIBS stepdeck_ui)
# Setup page on an EMIS SMC-IC4 (write-only: nothing may claim a verification).
stepdeck_add_test(tst_emissetup SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_emissetup.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../EmisUiFixture.h
                  LABELS ui LIBS stepdeck_ui)
# The load-from-file diff (changes only) and the write confirmation (old -> new), as units.
foreach(_t tst_diffdialog tst_writepreview)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp LABELS ui LIBS stepdeck_ui)
endforeach()
# Which drives' columns the setup page shows on a bus of many drives (issue 32, step 5).
stepdeck_add_test(tst_setupdrivechooser SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_setupdrivechooser.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h
                  LABELS ui LIBS stepdeck_ui)
