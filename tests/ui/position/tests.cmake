# Position read-out: the estimate of a positioning move (pure).
stepdeck_add_test(tst_moveestimate SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_moveestimate.cpp
                  LABELS unit LIBS stepdeck_ui)
stepdeck_add_test(tst_softlimitsui SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_softlimitsui.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                  LABELS ui LIBS stepdeck_ui)
# Referencing progress by confirmed steps; Go-to by Enter and the end of an accepted move (issue 16).
foreach(_t tst_referenceprogress tst_gotowidget)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h ${CMAKE_CURRENT_LIST_DIR}/../FakeGamepadDevice.h
                    LABELS ui LIBS stepdeck_ui)
endforeach()
# The DRO digits' box: unchanged values cost no relayout and no repaint (issue 21).
stepdeck_add_test(tst_drovaluelabel SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drovaluelabel.cpp
                  LABELS ui LIBS stepdeck_ui)
