# Drive list of multi-drive models (Nanotec bus) against the in-process simulator.
stepdeck_add_test(tst_drivepanel SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drivepanel.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h LABELS ui LIBS stepdeck_ui)
# The closed-loop panel of the drive page (Nanotec manual 8.1) against the in-process simulator.
stepdeck_add_test(tst_closedlooppanel SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_closedlooppanel.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h LABELS ui LIBS stepdeck_ui)
# A drive's position error: the message names the button, the button clears it (issue 16).
stepdeck_add_test(tst_positionerrorreset SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_positionerrorreset.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../NanotecUiFixture.h LABELS ui LIBS stepdeck_ui)
