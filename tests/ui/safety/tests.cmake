# The safety bar, its banner, the safety shortcuts and STOP feedback (ui/safety/).
foreach(_t tst_safetyshortcuts tst_safetybar)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                    LABELS ui LIBS stepdeck_ui)
endforeach()
stepdeck_add_test(tst_safetybanner SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_safetybanner.cpp
                  LABELS unit LIBS stepdeck_ui)
