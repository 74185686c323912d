# Parts of stepdeck-bench (app/bench) with logic of their own; the bench's figures are not tests.
stepdeck_add_test(tst_wirepacer
                  SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_wirepacer.cpp
                          ${CMAKE_SOURCE_DIR}/app/bench/WirePacer.cpp
                          ${CMAKE_SOURCE_DIR}/app/bench/PreciseWakeup.cpp
                  LABELS unit)
stepdeck_test_includes(tst_wirepacer ${CMAKE_SOURCE_DIR}/app/bench)
