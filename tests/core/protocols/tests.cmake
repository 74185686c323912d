# Across models: the safety contract's fault-injection matrix through the generic interface.
stepdeck_add_test(tst_faultmatrix SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_faultmatrix.cpp
                  LABELS integration TIMEOUT 300)
# Across models: soft limits asserted at each model's simulator (issue 11).
stepdeck_add_test(tst_softlimitsmodels SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_softlimitsmodels.cpp
                  LABELS integration TIMEOUT 300)
# Across models: every registered model is complete -- descriptor, controller, simulator with
# its probes, scenario, soak profile, translated schema words (issue 17).
stepdeck_add_test(tst_modelcompleteness
                  SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_modelcompleteness.cpp
                  LABELS integration TIMEOUT 120)
stepdeck_test_definitions(tst_modelcompleteness STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
