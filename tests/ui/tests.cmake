# GUI tests (offscreen) against the in-process simulator through ControllerSession.
set(_ui_test_support ${CMAKE_CURRENT_LIST_DIR}/UiTestSupport.h)
foreach(_t tst_jogpanel tst_setuppage tst_gamepadjog tst_trafficconsole tst_statuspanel
           tst_referencepanel tst_chartspanel tst_translations)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp ${_ui_test_support}
                    LABELS ui LIBS stepdeck_ui)
endforeach()
stepdeck_test_definitions(tst_translations STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# Source policy: no modal or native dialog under ui/ (issue 7, rule 5).
stepdeck_add_test(tst_dialogpolicy SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_dialogpolicy.cpp LABELS unit)
stepdeck_test_definitions(tst_dialogpolicy STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
