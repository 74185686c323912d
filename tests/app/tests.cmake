# End-to-end tests of the executables (they run stepdeck-sim and stepdeck-cli as processes).
stepdeck_add_test(tst_cli_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_e2e.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_e2e stepdeck-cli stepdeck-sim)
stepdeck_add_test(tst_peer_vanish SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_peer_vanish.cpp
                  LABELS integration)
stepdeck_add_test(tst_cli_safety SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_safety.cpp
                  LABELS integration TIMEOUT 600)
stepdeck_test_depends(tst_cli_safety stepdeck-cli)
stepdeck_add_test(tst_sim_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sim_e2e.cpp
                  LABELS integration)
stepdeck_test_depends(tst_sim_e2e stepdeck-cli stepdeck-sim)
stepdeck_add_test(tst_sim_machine SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_sim_machine.cpp
                  LABELS integration)
stepdeck_test_depends(tst_sim_machine stepdeck-cli stepdeck-sim)
stepdeck_test_definitions(tst_sim_machine STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# Not a timed test: a short soak and replug run must finish without crash, hang or moving axes.
stepdeck_add_test(tst_soak_smoke SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_soak_smoke.cpp
                  LABELS integration TIMEOUT 600)
stepdeck_test_depends(tst_soak_smoke stepdeck-bench)
stepdeck_add_test(tst_cli_emis_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_emis_e2e.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_emis_e2e stepdeck-cli stepdeck-sim)
stepdeck_add_test(tst_cli_laser_e2e SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_laser_e2e.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_laser_e2e stepdeck-cli stepdeck-sim)
# The GUI binary as a desktop program: --help without a display, SIGTERM/SIGHUP end it cleanly.
stepdeck_add_test(tst_gui_signals SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_gui_signals.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_gui_signals stepdeck)
stepdeck_add_test(tst_port_permission SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_port_permission.cpp
                  LABELS integration)
stepdeck_test_depends(tst_port_permission stepdeck-cli)
# stepdeck-bench --gui-idle runs and prints figures (issue 10); not timed.
stepdeck_add_test(tst_guiidle_smoke SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_guiidle_smoke.cpp
                  LABELS integration TIMEOUT 120)
stepdeck_test_depends(tst_guiidle_smoke stepdeck-bench stepdeck-sim stepdeck)
stepdeck_add_test(tst_panicload_smoke SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_panicload_smoke.cpp
                  LABELS integration TIMEOUT 120)
stepdeck_test_depends(tst_panicload_smoke stepdeck-bench)
# stepdeck-bench --jog-latency drives the GUI's jog panel offscreen (issue 21, item 4); not timed.
stepdeck_add_test(tst_joglatency_smoke SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_joglatency_smoke.cpp
                  LABELS integration TIMEOUT 120)
stepdeck_test_depends(tst_joglatency_smoke stepdeck-bench)
# The closed-loop workflow of Nanotec drives (manual 8.1) through stepdeck-cli on a pty.
stepdeck_add_test(tst_cli_closedloop SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_closedloop.cpp
                  LABELS integration TIMEOUT 300)
stepdeck_test_depends(tst_cli_closedloop stepdeck-cli)
# stepdeck-cli machine check: machine descriptions validated without opening anything.
stepdeck_add_test(tst_cli_machine SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_machine.cpp
                  LABELS integration)
stepdeck_test_depends(tst_cli_machine stepdeck-cli)
stepdeck_test_definitions(tst_cli_machine STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# stepdeck-cli --machine FILE: an E-LAB and a Nanotec simulator on two ptys as one machine.
stepdeck_add_test(tst_cli_machine_run SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_machine_run.cpp
                  LABELS integration TIMEOUT 600)
stepdeck_test_depends(tst_cli_machine_run stepdeck-cli)
# stepdeck-cli --model/--port without a file: a machine of that one controller (issue 19).
stepdeck_add_test(tst_cli_single_machine SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cli_single_machine.cpp
                  LABELS integration)
stepdeck_test_depends(tst_cli_single_machine stepdeck-cli)
# stepdeck-bench --poll-only: every model's poll against its paced wire (issue 21); not timed.
stepdeck_add_test(tst_pollwire_smoke SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_pollwire_smoke.cpp
                  LABELS integration TIMEOUT 180)
stepdeck_test_depends(tst_pollwire_smoke stepdeck-bench)
