stepdeck_add_test(tst_softlimitsui SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_softlimitsui.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                  LABELS ui LIBS stepdeck_ui)
# Referencing progress by confirmed groups (issue 16).
foreach(_t tst_referenceprogress)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/../UiTestSupport.h
                    LABELS ui LIBS stepdeck_ui)
endforeach()
# The DRO digits' box: unchanged values cost no relayout and no repaint (issue 21).
stepdeck_add_test(tst_drovaluelabel SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drovaluelabel.cpp
                  LABELS ui LIBS stepdeck_ui)
