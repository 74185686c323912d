# LinuxCNC's language (issue 33): expressions, parameters, O-word structure and control flow,
# and the worked-out program the check and the run share.
foreach(_t tst_ngcexpression tst_ngcparameters tst_ngcinterpreter tst_programexpansion)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp LABELS unit)
endforeach()
