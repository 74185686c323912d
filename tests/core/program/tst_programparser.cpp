// The program parser (issue 20, docs/programs.md): a golden table of every word, the modal
// state each block carries, every error with its line and column, repeats and their
// partners, and the stream: byte by byte, random chunks and garbage give the same result.
#include "ProgramParserTestSupport.h"
#include "TestMain.h"
#include "program/ProgramParser.h"
#include <QRandomGenerator>
#include <QtTest>

using namespace stepdeck::program;

using namespace stepdeck::program::parsertest;

class TestProgramParser : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void parse_everyWord_golden_data();
    void parse_everyWord_golden();
    void parse_invalid_lineColumnAndMessage_data();
    void parse_invalid_lineColumnAndMessage();
    void parse_severalErrors_everyOneListedInLineOrder();
    void parse_repeats_nestedPartners();
    void parse_repeatErrors_named_data();
    void parse_repeatErrors_named();
    void feed_byteByByteAndRandomChunks_sameProgram();
    void feed_garbage_errorsNeverCrashes();
    void feed_overlongLine_boundedAndNamed();
    void parse_crlfAndNoFinalNewline_sameBlocks();
    void parse_wordColumns_keptForTheCheck();
};

void TestProgramParser::parse_everyWord_golden_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QStringList>("blocks");
    QTest::newRow("G0") << "G0 X10 Y-2.5" << QStringList{"1: G0 X=10 Y=-2.5 abs mm F-"};
    QTest::newRow("G1 with F") << "G1 X1 F300" << QStringList{"1: G1 X=1 abs mm F300"};
    QTest::newRow("F modal") << "F120\nG1 Z-1"
                             << QStringList{"1: modal abs mm F120", "2: G1 Z=-1 abs mm F120"};
    QTest::newRow("motion modal") << "G1 X1 F60\nY2\nG0\nA90"
                                  << QStringList{"1: G1 X=1 abs mm F60", "2: G1 Y=2 abs mm F60",
                                                 "3: modal abs mm F60", "4: G0 A=90 abs mm F60"};
    // LinuxCNC: a motion word alone sets the modal motion (and F): the line moves nothing.
    QTest::newRow("bare G1 and G1 F")
        << "G1\nG1 F12\nX3\nG0\nG1 F5 (feed only)\nY1"
        << QStringList{"1: modal abs mm F-",  "2: modal abs mm F12", "3: G1 X=3 abs mm F12",
                       "4: modal abs mm F12", "5: modal abs mm F5",  "6: G1 Y=1 abs mm F5"};
    QTest::newRow("G91 G90") << "G91 G0 X1\nX1\nG90 X0"
                             << QStringList{"1: G0 X=1 rel mm F-", "2: G0 X=1 rel mm F-",
                                            "3: G0 X=0 abs mm F-"};
    QTest::newRow("G20 G21") << "G20\nG0 X1\nG21 X2"
                             << QStringList{"1: modal abs in F-", "2: G0 X=1 abs in F-",
                                            "3: G0 X=2 abs mm F-"};
    QTest::newRow("G28 all") << "G28" << QStringList{"1: G28 abs mm F-"};
    QTest::newRow("G28 axes") << "G28 Z0 X0" << QStringList{"1: G28 X=0 Z=0 abs mm F-"};
    QTest::newRow("G4") << "G4 P1.5" << QStringList{"1: G4 abs mm F- 1.5s"};
    QTest::newRow("M0 prompt") << "M0 (Load the part)"
                               << QStringList{"1: M0 abs mm F- \"Load the part\""};
    QTest::newRow("M1 prompt") << "M1 (Check the clamps)"
                               << QStringList{"1: M1 abs mm F- \"Check the clamps\""};
    QTest::newRow("M1 bare") << "N5 M1" << QStringList{"1: M1 abs mm F- \"\""};
    QTest::newRow("M2") << "M2" << QStringList{"1: M2 abs mm F-"};
    QTest::newRow("M30") << "M30" << QStringList{"1: M2 abs mm F-"};
    QTest::newRow("M3 S") << "M3 S1200" << QStringList{"1: M3 abs mm F- 1200rpm"};
    QTest::newRow("M4 S") << "M4 S12000" << QStringList{"1: M4 abs mm F- 12000rpm"};
    QTest::newRow("S before M4") << "S800 M4" << QStringList{"1: M4 abs mm F- 800rpm"};
    QTest::newRow("M5") << "M5" << QStringList{"1: M5 abs mm F-"};
    QTest::newRow("M7 M8 M9") << "M7\nM8\nM9"
                              << QStringList{"1: M7 abs mm F-", "2: M8 abs mm F-",
                                             "3: M9 abs mm F-"};
    QTest::newRow("M64 M65") << "M64 P2\nM65 P2"
                             << QStringList{"1: M64 abs mm F- P2", "2: M65 abs mm F- P2"};
    QTest::newRow("M66 high") << "M66 P1 L3 Q5" << QStringList{"1: M66 abs mm F- P1 high 5s"};
    QTest::newRow("M66 low") << "M66 P0 L4 Q0.5" << QStringList{"1: M66 abs mm F- P0 low 0.5s"};
    QTest::newRow("N numbers") << "N10 G0 X1\nN20 M5"
                               << QStringList{"1: G0 X=1 abs mm F-", "2: M5 abs mm F-"};
    QTest::newRow("comments and blanks") << "; header\n\n(only a comment)\nG0 X1 ; move\n"
                                         << QStringList{"4: G0 X=1 abs mm F-"};
    QTest::newRow("repeat") << "O1 repeat [3]\nG91 G0 X1\nO1 endrepeat"
                            << QStringList{"1: O repeat abs mm F- x3", "2: G0 X=1 rel mm F-",
                                           "3: O endrepeat abs mm F-"};
    QTest::newRow("lower case") << "g1 x1 f10" << QStringList{"1: G1 X=1 abs mm F10"};
    // Issue 29: T selects (modal), M6 changes by hand (a pause with its prompt).
    // LinuxCNC's "(MSG, text)": a line of its own is a block that only says it.
    QTest::newRow("MSG")
        << "(MSG, Clamp the part)\nG0 X1 (msg,moving on)\n( MSG ,no: not a message)\n(a MSG, no)"
        << QStringList{"1: modal abs mm F- msg\"Clamp the part\"",
                       "2: G0 X=1 abs mm F- msg\"moving on\""};
    QTest::newRow("T M6 on one line")
        << "T1 M6" << QStringList{"1: M6 abs mm F- T1 \"Load tool 1\""};
    QTest::newRow("T before, M6 with a comment")
        << "T12\nG0 X1\nM6 (ball nose D3)\nT0\nM6"
        << QStringList{"1: modal abs mm F-", "2: G0 X=1 abs mm F-",
                       "3: M6 abs mm F- T12 \"Load tool 12 (ball nose D3)\"", "4: modal abs mm F-",
                       "5: M6 abs mm F- T0 \"Load tool 0\""};
    // The modes CAM posts set in their headers (issue 29): lines that move nothing.
    QTest::newRow("CAM safety line") << "G17 G21 G40 G49 G80 G90 G94\nG0 X1"
                                     << QStringList{"1: modal abs mm F-", "2: G0 X=1 abs mm F-"};
    QTest::newRow("arc centre modes and return modes")
        << "G91.1\nG90.1\nG98\nG99"
        << QStringList{"1: modal abs mm F-", "2: modal abs mm F-", "3: modal abs mm F-",
                       "4: modal abs mm F-"};
    QTest::newRow("G80 beside other modes")
        << "G0 X1\nG80 G90 G17\nG0 X2"
        << QStringList{"1: G0 X=1 abs mm F-", "2: modal abs mm F-", "3: G0 X=2 abs mm F-"};
    // Arcs (issue 29): the centre by I J K or R, the plane, P turns, modal G2/G3, G90.1.
    QTest::newRow("G2 with I J") << "G2 X10 Y0 I5 J0 F300"
                                 << QStringList{"1: G2 X=10 Y=0 abs mm F300 G17 I5 J0 P1"};
    QTest::newRow("G3 with R, modal afterwards")
        << "G1 F100\nG3 X5 Y5 R5\nX0 Y10 R-5"
        << QStringList{"1: modal abs mm F100", "2: G3 X=5 Y=5 abs mm F100 G17 R5 P1",
                       "3: G3 X=0 Y=10 abs mm F100 G17 R-5 P1"};
    QTest::newRow("full circle, one centre word")
        << "F200 G2 I-5" << QStringList{"1: G2 abs mm F200 G17 I-5 P1"};
    QTest::newRow("helix with turns")
        << "G91 G3 Z-3 I4 P3 F50" << QStringList{"1: G3 Z=-3 rel mm F50 G17 I4 P3"};
    QTest::newRow("G18 takes I and K")
        << "G18 G2 X2 Z0 I1 K0 F60" << QStringList{"1: G2 X=2 Z=0 abs mm F60 G18 I1 K0 P1"};
    QTest::newRow("G19 takes J and K, G90.1")
        << "G19 G90.1 G3 Y1 Z1 J0 K1 F60"
        << QStringList{"1: G3 Y=1 Z=1 abs mm F60 G19 J0 K1 P1 G90.1"};
    QTest::newRow("inch arc") << "G20 G2 X1 Y1 I0.5 J0.5 F10"
                              << QStringList{"1: G2 X=1 Y=1 abs in F10 G17 I0.5 J0.5 P1"};
    // Issue 50 item 8: a zero offset along the plane's normal is left out, as GRBL does.
    QTest::newRow("G17 arc with K0.000 (FreeCAD's grbl post)")
        << "G2 X10.000 Y0.000 I5.000 J0.000 K0.000 F300.000"
        << QStringList{"1: G2 X=10 Y=0 abs mm F300 G17 I5 J0 P1"};
    QTest::newRow("G18 arc with J0")
        << "G18 G3 X2 Z0 I1 J0 K0 F60" << QStringList{"1: G3 X=2 Z=0 abs mm F60 G18 I1 K0 P1"};
    QTest::newRow("G19 arc with I-0, modal")
        << "G19 G2 Y2 Z0 J1 F60\nY0 Z2 I-0 J0 K1"
        << QStringList{"1: G2 Y=2 Z=0 abs mm F60 G19 J1 P1",
                       "2: G2 Y=0 Z=2 abs mm F60 G19 J0 K1 P1"};
    // Coordinates (issue 29): G54..G59 modal, G53 for one block, G10 L2/L20, G92 and its kin.
    QTest::newRow("G55 then G54") << "G0 X1\nG55 G0 X2\nX3\nG54"
                                  << QStringList{"1: G0 X=1 abs mm F-", "2: G0 X=2 abs mm F- G55",
                                                 "3: G0 X=3 abs mm F- G55",
                                                 "4: modal abs mm F- G54"};
    QTest::newRow("G53 for one block")
        << "G59\nG53 G0 Z0\nG0 X1"
        << QStringList{"1: modal abs mm F- G59", "2: G0 Z=0 abs mm F- G59 G53",
                       "3: G0 X=1 abs mm F- G59"};
    QTest::newRow("G53 with modal G1")
        << "G1 X1 F10\nG53 Y2" << QStringList{"1: G1 X=1 abs mm F10", "2: G1 Y=2 abs mm F10 G53"};
    QTest::newRow("G10 L2 and L20")
        << "G10 L2 P2 X10 Y-5\nG10 L20 P0 Z0"
        << QStringList{"1: G10 X=10 Y=-5 abs mm F- P2 L2", "2: G10 Z=0 abs mm F- P0 L20"};
    QTest::newRow("G92 family") << "G92 X0 Y0\nG92.2\nG92.3\nG92.1"
                                << QStringList{"1: G92 X=0 Y=0 abs mm F-", "2: G92.2 abs mm F-",
                                               "3: G92.3 abs mm F-", "4: G92.1 abs mm F-"};
    // Tool length offsets (issue 29): G43 H, G43 with the tool M6 loaded, G49.
    QTest::newRow("T M6 G43 H on one line")
        << "T1 M6 G43 H1\nG0 Z5"
        << QStringList{"1: M6 abs mm F- T1 \"Load tool 1\" H1 G43", "2: G0 Z=5 abs mm F- H1"};
    QTest::newRow("G43 takes the loaded tool, not the next selected")
        << "T2 M6\nT3\nG0 X0\nG43 Z15\nG49 G0 Z20"
        << QStringList{"1: M6 abs mm F- T2 \"Load tool 2\"", "2: modal abs mm F-",
                       "3: G0 X=0 abs mm F-", "4: G0 Z=15 abs mm F- H2 G43",
                       "5: G0 Z=20 abs mm F-"};
    QTest::newRow("G43 H0") << "G43 H0 G0 Z1" << QStringList{"1: G0 Z=1 abs mm F- H0 G43"};
    QTest::newRow("G80 ends modal arcs")
        << "G2 X1 I1 F10\nG80\nG0 X0"
        << QStringList{"1: G2 X=1 abs mm F10 G17 I1 P1", "2: modal abs mm F10",
                       "3: G0 X=0 abs mm F10"};
}

void TestProgramParser::parse_everyWord_golden()
{
    QFETCH(QString, program);
    QFETCH(QStringList, blocks);
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(program.toUtf8(), kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QCOMPARE(describeAll(*p), blocks);
    QVERIFY(errors.isEmpty());
}

void TestProgramParser::parse_invalid_lineColumnAndMessage_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error"); // "line:column: message" starts with this
    QTest::newRow("unknown G") << "G0 X1\nG12.5 X1 Y1"
                               << "2:1: G12.5 is not supported";
    // Issue 50: what StepDeck knows it does not run is named with what to do instead.
    QTest::newRow("a spline") << "G0 X1\nG5 X1 Y1"
                              << "2:1: G5 (a spline or NURBS curve) is not supported: let the CAM "
                                 "post write lines and arcs (G1, G2, G3)";
    QTest::newRow("probing") << "G38.2 Z-5 F10"
                             << "1:1: G38.2 (a probing move) is not supported: no controller of "
                                "StepDeck's has a probe input";
    QTest::newRow("tapping") << "G84 Z-1 R1 F10"
                             << "1:1: G84 (a tapping cycle) is not supported";
    QTest::newRow("boring")
        << "G85 Z-1 R1 F10"
        << "1:1: G85 (a boring cycle) is not supported: write the holes with G81";
    QTest::newRow("threading") << "G76 P1 Z-1"
                               << "1:1: G76 (threading with the spindle) is not supported";
    QTest::newRow("a lathe's surface speed") << "G96 S100"
                                             << "1:1: G96 (constant surface speed, a lathe's) is "
                                                "not supported: S is the spindle's rpm (G97)";
    QTest::newRow("a 3D printer's temperature") << "M104 S200"
                                                << "1:1: M104 is a 3D printer's word";
    QTest::newRow("a user M code") << "M101"
                                   << "1:1: M101 (a user-defined M code";
    QTest::newRow("synchronized output") << "M62 P1"
                                         << "1:1: M62 (an output switched with the next move) is "
                                            "not supported: M64 and M65 switch it at once";
    QTest::newRow("G54 and G55") << "G54 G55"
                                 << "1:5: G54 and G55 on one line: they are of one modal group";
    QTest::newRow("G59.1") << "G59.1"
                           << "1:1: G59.1 is not supported";
    QTest::newRow("G53 in G91") << "G91\nG53 G0 X1"
                                << "2:1: G53 takes absolute machine coordinates: not in G91";
    QTest::newRow("G53 with an arc") << "G53 G2 X1 I1 F10"
                                     << "1:1: G53 moves in machine coordinates with G0 or G1 only";
    QTest::newRow("G53 twice") << "G53 G53 G0 X1"
                               << "1:5: G53 appears twice on the line";
    QTest::newRow("G10 L1") << "G10 L1 P1 Z2"
                            << "1:5: G10 L1 is not supported: L2 and L20 set the coordinate "
                               "systems";
    QTest::newRow("G10 without L") << "G10 P1 X0"
                                   << "1:1: G10 needs L";
    QTest::newRow("G10 P7") << "G10 L2 P7 X0"
                            << "1:8: P7: G10 sets P1 (G54) to P6 (G59), P0 the system in effect";
    QTest::newRow("G10 R") << "G10 L2 P1 R45"
                           << "1:11: R45: G10 R (a rotated coordinate system) is not supported";
    QTest::newRow("G92 without axes") << "G92"
                                      << "1:1: G92 needs axis words";
    // Issue 50: G92.1 takes no axis words; with a motion in effect they are its move.
    QTest::newRow("G92.1 with axes") << "G92.1 X0"
                                     << "1:7: axis words need G0, G1, G2 or G3 before them";
    QTest::newRow("G92.1 with P") << "G92.1 P2"
                                  << "1:7: P2 is not used by G92.1";
    QTest::newRow("arc without centre") << "G0 X1\nG2 X1 Y1 F10"
                                        << "2:1: G2 needs its centre: I and J, or R";
    QTest::newRow("arc without F") << "G3 X1 I1"
                                   << "1:1: G3 needs a feed rate: F on this line or an earlier one";
    QTest::newRow("arc R and I")
        << "G2 X1 I1 R1 F10"
        << "1:10: R1: an arc takes its centre by I, J, K or by R, not both";
    QTest::newRow("arc K in G17") << "G2 X1 K1 F10"
                                  << "1:7: K1 is not used by G2 in the XY plane (G17): its centre "
                                     "takes I and J";
    QTest::newRow("arc J in G18") << "G18 G2 X1 J1 F10"
                                  << "1:11: J1 is not used by G2 in the XZ plane (G18): its "
                                     "centre takes K and I";
    QTest::newRow("arc K0.001 in G17: only 0 is left out")
        << "G2 X1 I1 K0.001 F10"
        << "1:10: K0.001 is not used by G2 in the XY plane (G17): its centre takes I and J";
    QTest::newRow("arc with K0 alone has no centre") << "G2 X1 K0 F10"
                                                     << "1:1: G2 needs its centre: I and J, or R";
    QTest::newRow("arc R without end in plane")
        << "G2 Z1 R3 F10"
        << "1:7: G2 with R needs an end point in the plane (X or Y); a full circle takes I and J";
    QTest::newRow("arc R zero") << "G2 X1 R0 F10"
                                << "1:7: R0: the radius must not be 0";
    QTest::newRow("arc A axis") << "G2 X1 A5 I1 F10"
                                << "1:7: A5: G2 in the XY plane (G17) moves X, Y and Z only";
    QTest::newRow("arc turns fraction") << "G2 I1 P1.5 F10"
                                        << "1:7: P1.5: P counts the arc's turns, a whole number "
                                           "1..1000";
    QTest::newRow("arc turns zero") << "G2 I1 P0 F10"
                                    << "1:7: P0: P counts the arc's turns";
    QTest::newRow("I with G1") << "G1 X1 I1 F10"
                               << "1:7: I1 is not used by G1";
    QTest::newRow("arc plus G0") << "G0 G2 X1 I1 F10"
                                 << "1:4: G0 and G2 on one line: they are of one modal group";
    QTest::newRow("unknown M") << "M18"
                               << "1:1: M18 is not supported";
    QTest::newRow("spindle orientation") << "M19"
                                         << "1:1: M19 (orienting the spindle) is not supported";
    QTest::newRow("M6 without T") << "G0 X1\nM6"
                                  << "2:1: M6 needs a tool: T on this line or an earlier one";
    QTest::newRow("T fraction") << "T1.5 M6"
                                << "1:1: T1.5: T takes a tool number, whole, 0..99999";
    QTest::newRow("T negative") << "T-2"
                                << "1:1: T-2: T takes a tool number";
    QTest::newRow("T twice") << "T1 T2 M6"
                             << "1:4: T appears twice on the line";
    QTest::newRow("fractional G") << "G0.5"
                                  << "1:1: G0.5 is not supported";
    QTest::newRow("unknown letter") << "G0 X1 E2"
                                    << "1:7: E2 is not a word";
    QTest::newRow("D without G41") << "G0 X1 D2"
                                   << "1:7: D2 is not used by G0";
    QTest::newRow("axis not on machine") << "G0 B5"
                                         << "1:4: the machine has no axis B";
    QTest::newRow("axis twice") << "G0 X1 X2"
                                << "1:7: axis X appears twice";
    QTest::newRow("parameter twice") << "G4 P1 P2"
                                     << "1:7: P appears twice";
    // Issue 50: LinuxCNC's whole line ("G0 X1 M0" moves, then holds): two motions do not.
    QTest::newRow("two motions") << "G0 X1 G1 Y1 F10"
                                 << "1:7: G0 and G1 on one line: they are of one modal group";
    QTest::newRow("G90 and G91") << "G90 G91"
                                 << "1:5: G90 and G91 on one line";
    QTest::newRow("G20 and G21") << "G20 G21"
                                 << "1:5: G20 and G21 on one line";
    QTest::newRow("axes before motion") << "X1"
                                        << "1:1: axis words need G0, G1, G2 or G3";
    QTest::newRow("G1 without F") << "G1 X1"
                                  << "1:1: G1 needs a feed rate";
    QTest::newRow("F zero") << "G1 X1 F0"
                            << "1:7: F0: the feed rate must be greater than 0";
    QTest::newRow("F negative") << "F-5"
                                << "1:1: F-5: the feed rate must be greater";
    QTest::newRow("G4 without P") << "G4"
                                  << "1:1: G4 needs P";
    QTest::newRow("G4 negative") << "G4 P-1"
                                 << "1:4: P-1 must lie within 0..1000000";
    QTest::newRow("G4 with axis") << "G4 P1 X1"
                                  << "1:7: X1 is not used by G4";
    QTest::newRow("S below 0") << "G0 X1 S-100"
                               << "1:7: S-100 must lie within 0..1000000";
    QTest::newRow("M4 with an axis") << "M4 S100 X1"
                                     << "1:9: axis words need G0, G1, G2 or G3 before them";
    QTest::newRow("M4 with an axis and P") << "G0 X0\nM4 S100 X1 P2"
                                           << "2:12: P2 is not used by M4";
    QTest::newRow("M3 and M4") << "M3 M4 S100"
                               << "1:4: M3 and M4 on one line: they are of one modal group";
    QTest::newRow("M1 with P") << "M1 P2"
                               << "1:4: P2 is not used by M1";
    QTest::newRow("M64 without P") << "M64"
                                   << "1:1: M64 needs P";
    QTest::newRow("M64 fraction") << "M64 P1.5"
                                  << "1:5: P1.5: the number must be a whole";
    QTest::newRow("M66 without L") << "M66 P1 Q2"
                                   << "1:1: M66 needs L";
    QTest::newRow("M66 L1") << "M66 P1 L1 Q2"
                            << "1:8: L1: L3 waits for high, L4 for low";
    QTest::newRow("M66 without Q") << "M66 P1 L3"
                                   << "1:1: M66 needs Q";
    QTest::newRow("M66 Q zero") << "M66 P1 L3 Q0"
                                << "1:11: Q0 must be greater than 0 and at most 1000000";
    QTest::newRow("L without M66") << "M64 P1 L3"
                                   << "1:8: L3 is not used by M64";
    QTest::newRow("N not first") << "G0 N10 X1"
                                 << "1:4: N (a line number) stands only";
    QTest::newRow("N fraction") << "N1.5 G0"
                                << "1:1: N1.5: N takes a whole number";
    // Issue 50 item 3: a program number is the name only before the first block.
    QTest::newRow("program number after a block")
        << "G0 X1\nO1001"
        << "2:6: only \"O1001 repeat [count]\" and \"O1001 endrepeat\"";
    QTest::newRow("a second program number") << "O1001\nO1002"
                                             << "2:6: only \"O1002 repeat [count]\"";
    QTest::newRow("colon not before the first block") << "G0 X1\n:1001"
                                                      << "2:1: unexpected character \":\"";
    QTest::newRow("lexer error") << "G0\nG0 X1 #"
                                 << "2:7: unexpected character";
    QTest::newRow("missing value") << "G0 Y"
                                   << "1:5: Y needs a number";
    QTest::newRow("O with others") << "O1 repeat [2] G0"
                                   << "1:15: O1 stands alone";
    QTest::newRow("O unknown keyword") << "O1 while [1]"
                                       << "1:4: only \"O1 repeat [count]\"";
    QTest::newRow("repeat without count") << "O1 repeat\nO1 endrepeat"
                                          << "1:4: repeat needs a count";
    QTest::newRow("repeat too many") << "O1 repeat [1000001]\nO1 endrepeat"
                                     << "1:12: the repeat count must be a whole number";
    // Issue 29: LinuxCNC's modal groups, one word of each a line; the modes StepDeck does not
    // run are refused with what to do instead.
    QTest::newRow("two planes") << "G17 G18"
                                << "1:5: G17 and G18 on one line: they are of one "
                                   "modal group";
    QTest::newRow("two path modes") << "G61 G64"
                                    << "1:5: G61 and G64 on one line";
    QTest::newRow("G80 and G0") << "G80 G0 X1"
                                << "1:5: G80 and G0 on one line";
    QTest::newRow("G0 and G80") << "G0 G80 X1"
                                << "1:4: G0 and G80 on one line";
    QTest::newRow("G80 cancels the motion") << "G0 X1\nG80\nX2"
                                            << "3:1: axis words need G0, G1, G2 or G3";
    // Issue 50 item 7: cutter compensation (tst_cuttercompensation has the rest).
    QTest::newRow("G41 and G40") << "G41.1 D2 G40"
                                 << "1:10: G41.1 and G40 on one line: they are of one modal group";
    QTest::newRow("G42.1 without D") << "G42.1"
                                     << "1:1: G42.1 needs D: the tool's diameter";
    QTest::newRow("G41 D fraction") << "G41 D1.5"
                                    << "1:5: D1.5: D takes a tool number, whole, 0..99999 (G41.1 "
                                       "D takes a diameter)";
    QTest::newRow("G43 without H or a loaded tool")
        << "T1\nG0 X1\nG43 Z5"
        << "3:1: G43 needs H<n> or a tool loaded by M6 (T<n> M6) before it";
    QTest::newRow("H without G43") << "G0 X1 H2"
                                   << "1:7: H2 is used only with G43";
    QTest::newRow("H fraction") << "G43 H1.5"
                                << "1:5: H1.5: H takes a tool number, whole, 0..99999";
    QTest::newRow("G43.1") << "G43.1 Z1"
                           << "1:1: G43.1 (a tool length written in the program) is not "
                              "supported";
    QTest::newRow("G95") << "G95"
                         << "1:1: G95 (feed per revolution) is not supported";
    QTest::newRow("G64 P negative") << "G64 P-0.1"
                                    << "1:5: P-0.1: G64 P is a tolerance";
    QTest::newRow("G61 with P") << "G61 P0.1"
                                << "1:5: P0.1 is not used on a line without an "
                                   "action";
    QTest::newRow("two decimals") << "G61.15"
                                  << "1:1: G61.15 is not supported";
    QTest::newRow("percent in the middle") << "G0 X1\n%\nG0 X2"
                                           << "2:1: \"%\" stands only on the program's first line";
    QTest::newRow("percent not closed") << "%\nG0 X1\n"
                                        << "2:1: the program opened with \"%\" (line 1) ends "
                                           "with neither \"%\" nor M2/M30";
}

void TestProgramParser::parse_invalid_lineColumnAndMessage()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    QList<ProgramError> errors;
    QVERIFY(!ProgramParser::parse(program.toUtf8(), kAxes, &errors));
    QCOMPARE(errors.size(), 1);
    QVERIFY2(errors.first().text().startsWith(error), qPrintable(errors.first().text()));
}

void TestProgramParser::parse_severalErrors_everyOneListedInLineOrder()
{
    QList<ProgramError> errors;
    QVERIFY(!ProgramParser::parse("O7 repeat [2]\nG0 Q1\nG0 X1\nM99\nG1 Y1\n", kAxes, &errors));
    QCOMPARE(
        texts(errors),
        (QStringList{
            "1:1: O7 repeat is not closed by O7 endrepeat", "2:4: Q1 is not used by G0",
            "4:1: M99 (a Fanuc-style subprogram) is not supported: write the subprogram as O<name> "
            "sub … endsub and call it with O<name> call",
            "5:1: G1 needs a feed rate: F on this line or an "
            "earlier one"}));
}

void TestProgramParser::parse_repeats_nestedPartners()
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(
        "O1 repeat [2]\nO2 repeat [3]\nG0 X1\nO2 endrepeat\nO1 endrepeat\nM2\n", kAxes, &errors);
    QVERIFY2(p, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QCOMPARE(p->allBlocks().size(), 6);
    QCOMPARE(p->allBlocks().at(0).partner, 4);
    QCOMPARE(p->allBlocks().at(4).partner, 0);
    QCOMPARE(p->allBlocks().at(1).partner, 3);
    QCOMPARE(p->allBlocks().at(3).partner, 1);
    QCOMPARE(p->allBlocks().at(1).count, qint64(3));
    QCOMPARE(p->lines, 6);
}

void TestProgramParser::parse_repeatErrors_named_data()
{
    QTest::addColumn<QString>("program");
    QTest::addColumn<QString>("error");
    QTest::newRow("endrepeat alone") << "O3 endrepeat"
                                     << "1:1: O3 endrepeat without its O3 repeat";
    QTest::newRow("crossed") << "O1 repeat [2]\nO2 repeat [2]\nO1 endrepeat\nO2 endrepeat"
                             << "3:1: O1 endrepeat does not close O2 repeat (line 2)";
    QTest::newRow("unclosed") << "G0 X1\nO5 repeat [2]\nG0 X2"
                              << "2:1: O5 repeat is not closed by O5 endrepeat";
}

void TestProgramParser::parse_repeatErrors_named()
{
    QFETCH(QString, program);
    QFETCH(QString, error);
    QList<ProgramError> errors;
    QVERIFY(!ProgramParser::parse(program.toUtf8(), kAxes, &errors));
    QVERIFY2(texts(errors).contains(error), qPrintable(texts(errors).join(QLatin1Char('\n'))));
}

void TestProgramParser::feed_byteByByteAndRandomChunks_sameProgram()
{
    const QByteArray text = "; pick and place\nG21 G90\nG28\nO1 repeat [3]\n  G91 G1 X2.5 A-90 "
                            "F600 (step)\n  M64 P1\n  G4 P0.25\n  M65 P1\nO1 endrepeat\nM0 (Check "
                            "the part \xc3\xa4)\nM30\n";
    QList<ProgramError> errors;
    const std::optional<Program> whole = ProgramParser::parse(text, kAxes, &errors);
    QVERIFY2(whole, qPrintable(texts(errors).join(QLatin1Char('\n'))));
    QCOMPARE(whole->allBlocks().last().kind, BlockKind::End);
    QCOMPARE(whole->allBlocks().at(whole->allBlocks().size() - 2).prompt,
             QStringLiteral("Check the part \u00e4"));
    // The blocks as the parser gives them out while it reads (the streamed program), and as
    // they are read back from the source by the index.
    const QList<ProgramBlock> blocks = whole->allBlocks();
    const auto streamed = [](ProgramParser& parser, QList<ProgramBlock>* out) {
        parser.setSink([out](ProgramBlock&& b) { *out << b; });
    };
    ProgramParser byByte(kAxes);
    QList<ProgramBlock> byByteBlocks;
    streamed(byByte, &byByteBlocks);
    for (const char c : text)
        byByte.feed(QByteArray(1, c));
    QVERIFY(byByte.finish(nullptr));
    // A RepeatStart goes out before its endrepeat is read: its partner comes from the index.
    QCOMPARE(byByteBlocks.at(2).partner, -1);
    byByteBlocks[2].partner = blocks.at(2).partner;
    QCOMPARE(byByteBlocks, blocks);
    QRandomGenerator random(20);
    for (int round = 0; round < 50; ++round) {
        ProgramParser chunked(kAxes);
        for (qsizetype at = 0; at < text.size();) {
            const qsizetype n = random.bounded(1, 12);
            chunked.feed(text.mid(at, n));
            at += n;
        }
        std::optional<Program> p = chunked.finish(nullptr);
        QVERIFY(p);
        p->source = ProgramSource::bytes(text);
        QCOMPARE(p->allBlocks(), blocks);
    }
}

void TestProgramParser::feed_garbage_errorsNeverCrashes()
{
    QRandomGenerator random(7);
    for (int round = 0; round < 200; ++round) {
        QByteArray garbage(random.bounded(0, 400), Qt::Uninitialized);
        for (char& c : garbage)
            c = char(random.bounded(256));
        QList<ProgramError> errors;
        const std::optional<Program> p = ProgramParser::parse(garbage, kAxes, &errors);
        QVERIFY(p.has_value() == errors.isEmpty());
        QVERIFY(errors.size() <= ProgramParser::kMaxErrors + 1);
        for (const ProgramError& e : errors)
            QVERIFY(e.line >= 1 && e.column >= 1 && !e.message.isEmpty());
    }
}

void TestProgramParser::feed_overlongLine_boundedAndNamed()
{
    ProgramParser parser(kAxes);
    parser.feed("G0 X1\n(");
    const QByteArray chunk(4096, 'a');
    for (int i = 0; i < 100; ++i)
        parser.feed(chunk); // 400 KiB without a newline: never buffered whole
    parser.feed(")\nG0 X2\n");
    QList<ProgramError> errors;
    QVERIFY(!parser.finish(&errors));
    QCOMPARE(texts(errors),
             QStringList{QStringLiteral("2:1025: the line is longer than 1024 characters")});
}

void TestProgramParser::parse_crlfAndNoFinalNewline_sameBlocks()
{
    QList<ProgramError> errors;
    const auto lf = ProgramParser::parse("G0 X1\nG4 P2\nM2", kAxes, &errors);
    const auto dos = ProgramParser::parse("G0 X1\r\nG4 P2\r\nM2\r\n", kAxes, &errors);
    QVERIFY(lf && dos);
    QCOMPARE(dos->allBlocks(), lf->allBlocks());
    QCOMPARE(lf->allBlocks().last().text, QStringLiteral("M2"));
}

// ProgramCheck names the word it refuses: each block keeps where its words stand.
void TestProgramParser::parse_wordColumns_keptForTheCheck()
{
    QList<ProgramError> errors;
    const std::optional<Program> p = ProgramParser::parse(
        "N10 g1 x 1.5  F300\nY2\nM64 P2\nO1 repeat [2]\n  O1 endrepeat\nM66 L3 P1 Q2", kAxes,
        &errors);
    QVERIFY(p);
    QCOMPARE(p->allBlocks().size(), 6);
    const auto columns = [&](int i) { return p->allBlocks().at(i).columns; };
    QCOMPARE(columns(0), (WordMap<QString, int>{{"X", 8}, {"F", 15}}));
    QCOMPARE(p->allBlocks().at(0).actionColumn, 5);
    QCOMPARE(columns(1), (WordMap<QString, int>{{"Y", 1}}));
    QCOMPARE(p->allBlocks().at(1).actionColumn, 0); // moves with the G1 before it
    QCOMPARE(p->allBlocks().at(1).columnOf("F"), 1);
    QCOMPARE(columns(2), (WordMap<QString, int>{{"P", 5}}));
    QCOMPARE(p->allBlocks().at(2).actionColumn, 1);
    QCOMPARE(p->allBlocks().at(3).actionColumn, 1);
    QCOMPARE(p->allBlocks().at(4).actionColumn, 3);
    QCOMPARE(columns(5), (WordMap<QString, int>{{"L", 5}, {"P", 8}, {"Q", 11}}));
    QCOMPARE(p->allBlocks().at(5).columnOf("F"), 1);
    QCOMPARE(p->allBlocks().at(0).columnOf("F"), 15);
    QCOMPARE(p->allBlocks().at(0).columnOf({}), 5);
}

STEPDECK_TEST_APPLESS_MAIN(TestProgramParser)
#include "tst_programparser.moc"
