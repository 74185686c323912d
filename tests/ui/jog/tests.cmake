# Jog safety (issue 7, rules 3 and 4) asserted at the in-process E-LAB simulator.
stepdeck_add_test(tst_jogsafety SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jogsafety.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui TIMEOUT 300)
# Jog by short targets (Capabilities::jogByTargets) against the in-process laser-axis simulator.
stepdeck_add_test(tst_targetjogger SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_targetjogger.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# A held jog never reverses when the layout moves under it (issue 16, safety contract rule 6).
stepdeck_add_test(tst_jogholdstill SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jogholdstill.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui TIMEOUT 300)
# The jog panel's stopping distance (issue 28 item 6).
stepdeck_add_test(tst_jogstopdistance SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jogstopdistance.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
