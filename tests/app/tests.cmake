# End-to-end tests of the executables (they run stepdeck-sim and stepdeck-cli as processes).
stepdeck_add_test(tst_cli_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_e2e.cpp
                  LABELS integration TIMEOUT 300)
add_dependencies(tst_cli_e2e stepdeck-cli stepdeck-sim)
stepdeck_add_test(tst_peer_vanish SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_peer_vanish.cpp
                  LABELS integration)
stepdeck_add_test(tst_cli_laser_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_laser_e2e.cpp
                  LABELS integration TIMEOUT 300)
add_dependencies(tst_cli_laser_e2e stepdeck-cli stepdeck-sim)
