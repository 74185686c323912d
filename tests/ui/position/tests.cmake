# Position read-out: the estimate of a positioning move (pure).
stepdeck_add_test(tst_moveestimate SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_moveestimate.cpp
                  LABELS unit LIBS stepdeck_ui)
stepdeck_add_test(tst_softlimitsui SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_softlimitsui.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
