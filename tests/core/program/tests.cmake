# Motion programs (issue 20): the G-code subset's lexer and parser.
stepdeck_add_test(tst_programlexer SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programlexer.cpp LABELS unit)
# A line's words in place (issue 29's check rate): against QMap, step by step.
stepdeck_add_test(tst_wordmap SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_wordmap.cpp LABELS unit)
stepdeck_add_test(tst_programparser SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programparser.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramParserTestSupport.h LABELS unit)
stepdeck_add_test(tst_programreader SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programreader.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
stepdeck_add_test(tst_programparserdialect SOURCES
                  ${CMAKE_CURRENT_LIST_DIR}/tst_programparserdialect.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramParserTestSupport.h LABELS unit)
# The check against a machine and the preview; the docs' example programs are read from the
# source tree.
stepdeck_add_test(tst_programcheck SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programcheck.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
stepdeck_test_definitions(tst_programcheck STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The check over a whole program: feed limits, run from a line, around the program, repeats.
stepdeck_add_test(tst_programcheckwhole SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programcheckwhole.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# The check of the dialect's coordinates, tools and spindle scale (issue 29).
stepdeck_add_test(tst_programcheckdialect SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programcheckdialect.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# Run from line N (issue 47 item 5): the start point the lines before it leave, the rapids to
# it (Z up first or down last) and the check of them and of the restored spindle.
stepdeck_add_test(tst_runfromline SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_runfromline.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# G41/G42 (issue 50 item 7): the tool's path worked out by hand, and LinuxCNC's refusals.
stepdeck_add_test(tst_cuttercompensation SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_cuttercompensation.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# Blocks lowered to motion commands, as rs274's canonical text (issue 49): goldens by hand.
stepdeck_add_test(tst_programlowering SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programlowering.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# The check's preview and the work coordinates it uses.
stepdeck_add_test(tst_programpreview SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programpreview.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# The runner on a machine of an E-LAB and a Nanotec simulator on two pseudo-terminals: its walk,
# and what each block sends.
# 300 s: tst_programrunnermotion runs about 100 s on its own (every row at the board), and
# under tools/test's 4 tests per core it came close to the default 120.
foreach(_t tst_programrunner tst_programrunnermotion tst_programcontour tst_programrunnerowner)
  stepdeck_add_test(${_t} SOURCES ${CMAKE_CURRENT_LIST_DIR}/${_t}.cpp
                    ${CMAKE_CURRENT_LIST_DIR}/ProgramRunnerTestSupport.h
                    ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration TIMEOUT 300)
endforeach()
# The rules the check and the run share (issue 28).
stepdeck_add_test(tst_programrules SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programrules.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ElabBoardTestSupport.h LABELS unit)
# Programs that check clean run to their end on the simulators: the check refuses first
# whatever the run would refuse (issue 28, item 1).
stepdeck_add_test(tst_programcheckedruns SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programcheckedruns.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration TIMEOUT 600)
# G2/G3 geometry (issue 29): the path the check and the run share.
stepdeck_add_test(tst_arcpath SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_arcpath.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MillTestSupport.h LABELS unit)
# G1's shares of F on controllers that coordinate (issue 30).
stepdeck_add_test(tst_coordinatedfeed SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_coordinatedfeed.cpp
                  LABELS unit)
# The same on the EMIS and Nanotec simulators, asserted at the device.
stepdeck_add_test(tst_programcoordinated SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_programcoordinated.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration)
# A machine's tool table in LinuxCNC's tool.tbl format (issue 29).
stepdeck_add_test(tst_tooltable SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_tooltable.cpp LABELS unit)
# Programs in the styles CAM posts write, run end to end on an E-LAB simulator (issue 29).
stepdeck_add_test(tst_camprograms SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_camprograms.cpp
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration TIMEOUT 600)
stepdeck_test_definitions(tst_camprograms
                           STEPDECK_CAM_DIR="${CMAKE_CURRENT_LIST_DIR}/cam")
# Drilling cycles G81, G82, G83, G73 (issue 29): the words and the moves the check and the run
# share.
stepdeck_add_test(tst_drillcycle SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_drillcycle.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/MillTestSupport.h LABELS unit)
# Which blocks run as one step stream and the moves they become (issue 30), and the check's
# refusal of a feed the stream's tick cannot carry.
stepdeck_add_test(tst_contourmoves SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_contourmoves.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# The MDI line's program of one line and its modal state (issue 31).
stepdeck_add_test(tst_mdisession SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_mdisession.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
# Programs in LinuxCNC's language (issue 33), our own in ngc/: checked, their preview path and
# blocks against moves worked out in the test, and broken copies refused at the source line.
stepdeck_add_test(tst_ngcprograms SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_ngcprograms.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/NgcProgramsTestSupport.h
                  ${CMAKE_CURRENT_LIST_DIR}/ProgramCheckTestSupport.h LABELS unit)
stepdeck_test_definitions(tst_ngcprograms STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The same programs run end to end on an E-LAB and an EMIS simulator, asserted at the device;
# a copy beyond the soft limits refused before anything moved.
stepdeck_add_test(tst_ngcrun SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_ngcrun.cpp
                  ${CMAKE_CURRENT_LIST_DIR}/NgcProgramsTestSupport.h
                  ${CMAKE_SOURCE_DIR}/tests/support/PtyDevice.h LABELS integration TIMEOUT 600)
stepdeck_test_definitions(tst_ngcrun STEPDECK_SOURCE_DIR="${CMAKE_SOURCE_DIR}")
# The work offsets of a machine's axes in their units (pure: store, conversion, persistence),
# kept in core since issue 49 item 4 (the window and the CLI read them there).
stepdeck_add_test(tst_machineworkoffsets SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_machineworkoffsets.cpp
                  LABELS unit)
