stepdeck_add_test(tst_lasercodec SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_lasercodec.cpp LABELS unit)
stepdeck_add_test(tst_lasersimaxis SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_lasersimaxis.cpp LABELS unit)
stepdeck_add_test(tst_laseraxissimulator SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laseraxissimulator.cpp
                  LABELS unit)
stepdeck_add_test(tst_laseraxiscontroller SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_laseraxiscontroller.cpp
                  LABELS unit)
