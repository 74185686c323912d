# Setup page on a Nanotec bus (read-back, unknown values, preview) against the bus simulator.
stepdeck_add_test(tst_nanotecsetup SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_nanotecsetup.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
