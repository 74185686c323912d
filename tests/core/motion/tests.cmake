# The motion layer (issue 30): canonical moves, their bounded queue, and contours laid on ticks
# as step streams.
stepdeck_add_test(tst_canonicalmove SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_canonicalmove.cpp LABELS unit)
stepdeck_add_test(tst_contoursteps SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_contoursteps.cpp LABELS unit)
stepdeck_add_test(tst_contourfeed SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_contourfeed.cpp LABELS unit)
