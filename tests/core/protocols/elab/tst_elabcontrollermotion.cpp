// ElabController motion against the real ElabSimulator: the manual's move rules, jog,
// stop/panic overtaking, reference, feed and the DC2 stream with XOFF/XON.
#include "ElabControllerRig.h"
#include "TestMain.h"

class TestElabControllerMotion : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void move_picksNarrowestCommand_data();
    void move_picksNarrowestCommand();
    void move_setupIncomplete_refused();
    void move_whileLimitSwitch_refusedWithReason();
    void move_outOfRange_notSent();
    void jog_allowedOnLimitSwitch();
    void jog_lease_expiry_sendsZero();
    void nak_readsBothStatusWords_andReportsDecodedBits();
    void timeout_resyncsWithSynBurst_data();
    void timeout_resyncsWithSynBurst();
    void stop_overtakesQueuedMoves();
    void statusRead_firstReplyLostDuringMove_moveStaysTracked();
    void panic_discardsQueue_andMarksUnreferenced();
    void reference_zeroesPosition_andMarksReferenced();
    void feed_singleAxis_clearPositionThenFeedSteps();
    void dc2Stream_xoffXon_noStepLostOrDuplicated();
    void feed_multiAxis_streamsStraightLine();
    void velocity_reversalWhileRunning_refused();
    void limitHitDuringMove_marksAxisUnreferenced();
    void dc2Stream_stop_flushesBufferAndEndsFeed();
    void jog_nak_haltsJogAndSaysWhy();
};

void TestElabControllerMotion::move_picksNarrowestCommand_data()
{
    QTest::addColumn<AxisVector>("steps");
    QTest::addColumn<QByteArray>("frame");
    QTest::newRow("Z only -> <BS>") << AxisVector{{Axis::Z, 1000}} << bytes("<BS>000003E8.");
    QTest::newRow("X only -> <FF>")
        << AxisVector{{Axis::X, 16}, {Axis::Z, 0}} << bytes("<FF>00000010,00000000;");
    QTest::newRow("XY -> <FF>") << AxisVector{{Axis::X, 1000}, {Axis::Y, -1000}}
                                << bytes("<FF>000003E8,FFFFFC18;");
    QTest::newRow("XYZ -> <EOT>") << AxisVector{{Axis::X, 1000}, {Axis::Y, -1000}, {Axis::Z, 16}}
                                  << bytes("<EOT>000003E8,FFFFFC18;00000010.");
}

void TestElabControllerMotion::move_picksNarrowestCommand()
{
    QFETCH(AxisVector, steps);
    QFETCH(QByteArray, frame);
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->moveRelative(id, steps); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    // Pre-flight (RequestAxeState, RequestMachineState), then the narrowest FastMove.
    const QList<QByteArray> out = rig.framesOut(false);
    QCOMPARE(out,
             (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(), frame}));
    for (auto it = steps.cbegin(); it != steps.cend(); ++it) {
        QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(it.key()), it.value(), 5000);
        QCOMPARE(rig.ctl->status().axes.value(it.key()).position, it.value());
        QVERIFY(!rig.ctl->status().axes.value(it.key()).positionKnown); // never referenced
    }
}

void TestElabControllerMotion::move_setupIncomplete_refused()
{
    Rig rig;
    QVERIFY(rig.connect());
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("tmInvSetup"), qPrintable(r.message));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::FF));
}

void TestElabControllerMotion::move_whileLimitSwitch_refusedWithReason()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitSwitchActuated(Axis::X, true);
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::Y, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("limit switch"), qPrintable(r.message));
    QVERIFY2(r.message.contains("tmLimSwX"), qPrintable(r.message));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::FF));
    QCOMPARE(rig.sim->position(Axis::Y), 0);
}

void TestElabControllerMotion::move_outOfRange_notSent()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, qint64(1) << 31}});
    });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains("2147483647"), qPrintable(r.message));
    r = rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::Z, 2}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::Y, 40000}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY2(r.message.contains("32767"), qPrintable(r.message));
    r = rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::U, 1}}); });
    QCOMPARE(r.error, ErrorKind::InvalidValue);
    QVERIFY(rig.framesOut(false).isEmpty());
}

void TestElabControllerMotion::jog_allowedOnLimitSwitch()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->setLimitSwitchActuated(Axis::X, true);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).limitSwitch, 5000);
    rig.ctl->setJogVelocity({{Axis::X, -300}});
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).jogging, 5000);
    QVERIFY(rig.jogRefusals->isEmpty());
    rig.ctl->endJog();
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QVERIFY(rig.indexOfFrame(encode::jogSpeed({0, 0, 0})) >= 0);
    QVERIFY(rig.ctl->status().axes.value(Axis::X).positionEstimated);
}

void TestElabControllerMotion::jog_lease_expiry_sendsZero()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    rig.ctl->setJogVelocity({{Axis::Y, 400}}); // never renewed
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::Y), 5000);
    // The first jog from idle was preceded by the standstill check.
    const QList<QByteArray> out = rig.framesOut(false);
    QVERIFY(out.size() >= 3);
    QCOMPARE(out.at(0), encode::requestAxeState());
    QCOMPARE(out.at(1), encode::requestMachineState());
    QCOMPARE(out.at(2).at(0), ctrl::DC4);
    QTRY_VERIFY_WITH_TIMEOUT(rig.indexOfFrame(encode::jogSpeed({0, 0, 0})) >= 0, 5000);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::Y), 5000);
    // The ramp goes idle on its own tick after the zero went out, not with the board's stop:
    // on a loaded machine the board can stand first.
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->jogRamp().isIdle(), 5000);
}

void TestElabControllerMotion::nak_readsBothStatusWords_andReportsDecodedBits()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->forceNak(1);
    rig.traffic->clear();
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, 100}});
    });
    QCOMPARE(r.error, ErrorKind::Nak);
    QVERIFY2(r.message.contains("NAK"), qPrintable(r.message));
    QVERIFY2(r.message.contains("tmDriveOn"), qPrintable(r.message)); // drive power is 100
    QVERIFY2(r.message.contains(describeAxeState(0)), qPrintable(r.message));
    const QList<QByteArray> out = rig.framesOut(false);
    QCOMPARE(out, (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(),
                                     bytes("<FF>00000064,00000000;"), encode::requestAxeState(),
                                     encode::requestMachineState()}));
    QCOMPARE(rig.sim->position(Axis::X), 0);
}

void TestElabControllerMotion::timeout_resyncsWithSynBurst_data()
{
    QTest::addColumn<bool>("corrupt");
    QTest::newRow("dropped reply") << false;
    QTest::newRow("corrupted reply") << true;
}

void TestElabControllerMotion::timeout_resyncsWithSynBurst()
{
    QFETCH(bool, corrupt);
    ControllerOptions o = defaultOptions();
    o.commandTimeoutMs = 300;
    Rig rig(o);
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    // Two replies: a poll's words go out back to back, and when only the first of them is lost
    // the second reply shows the line in step (no resynchronisation; tst_elabexchangequeue).
    if (corrupt)
        rig.sim->faults().corruptReplies = 2;
    else
        rig.sim->faults().dropReplies = 2;
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().resyncCount >= 1, 5000);
    // A burst of <SYN>, then RequestMachineState.
    const QByteArray burst(16, ctrl::SYN);
    QTRY_VERIFY_WITH_TIMEOUT(rig.indexOfFrame(burst) >= 0, 5000);
    const int at = rig.indexOfFrame(burst);
    QTRY_VERIFY_WITH_TIMEOUT(rig.framesOut(true).size() > at + 1, 5000);
    QCOMPARE(rig.framesOut(true).at(at + 1), encode::requestMachineState());
    QVERIFY(!rig.errors->isEmpty());
    QVERIFY2(rig.errors->first().at(0).toString().contains("resynchronising"),
             qPrintable(rig.errors->first().at(0).toString()));
    // The line works again.
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(rig.ctl->linkState(), LinkState::Connected);
}

// Pipelined, a status read's <ENQ> reply can come while its <HT> is asked again (the <HT> reply
// lost). The motion bookkeeping must judge the two new words together, never the new machine
// word with the <HT> word of the read before the move: that one showed the axes idle, the move
// would count as finished, and the next read would stop it as motion nobody commanded.
void TestElabControllerMotion::statusRead_firstReplyLostDuringMove_moveStaysTracked()
{
    ControllerOptions o = defaultOptions();
    o.pollIntervalMs = 60000; // only the reads of this test
    Rig rig(o);
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 100000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    rig.errors->clear();
    rig.sim->faults().dropReplies = 1; // the <HT> reply of the next read
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); }).ok());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); }).ok());
    QCOMPARE(rig.sim->countReceived(encode::stopMove()), 0);
    QVERIFY(rig.sim->isMoving(Axis::X));
    for (const QList<QVariant>& args : std::as_const(*rig.errors))
        QVERIFY2(!args.at(0).toString().contains("did not command"),
                 qPrintable(args.at(0).toString()));
    QVERIFY(rig.ctl->status().axes.value(Axis::X).moving);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
}

void TestElabControllerMotion::stop_overtakesQueuedMoves()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // A long move: 100000 steps at 5000 steps/s.
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 100000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->position(Axis::X) > 100, 5000);
    rig.traffic->clear();
    const RequestId second = rig.nextId++;
    const RequestId third = rig.nextId++;
    const RequestId stopId = rig.nextId++;
    rig.ctl->moveRelative(second, {{Axis::Y, 500}});
    rig.ctl->feed(third, {{Axis::Z, 500}});
    rig.ctl->stop(stopId);
    QVERIFY(rig.wait(stopId).ok());
    QCOMPARE(rig.wait(second).error, ErrorKind::Cancelled);
    QCOMPARE(rig.wait(third).error, ErrorKind::Cancelled);
    // The stop went out right behind what was already on the line (at most a status read's
    // two words, which go out back to back), nothing after it moved.
    const QList<QByteArray> out = rig.framesOut(true);
    const int stopAt = rig.indexOfFrame(encode::stopMove());
    QVERIFY(stopAt >= 0 && stopAt <= ElabExchangeQueue::kMaxPipelined);
    QCOMPARE(rig.indexOfFrame(bytes("<FF>00000000,000001F4;")), -1);
    QVERIFY(!rig.sentFrameStartingWith(ctrl::VT));
    QVERIFY(!rig.sentFrameStartingWith(ctrl::RS));
    // Braked to standstill, then RequestRelPosition corrected the host position.
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sentFrameStartingWith(ctrl::ETX), 5000);
    QTRY_COMPARE_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).position,
                              rig.sim->position(Axis::X), 5000);
    QVERIFY(rig.sim->position(Axis::X) < 100000);
    QCOMPARE(rig.sim->position(Axis::Y), 0);
    QCOMPARE(rig.countResults(second), 1);
    QCOMPARE(rig.countResults(stopId), 1);
}

void TestElabControllerMotion::panic_discardsQueue_andMarksUnreferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 50000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    rig.traffic->clear();
    const RequestId queued = rig.nextId++;
    const RequestId panicId = rig.nextId++;
    rig.ctl->moveRelative(queued, {{Axis::Y, 10}});
    rig.ctl->panic(panicId);
    QVERIFY(rig.wait(panicId).ok());
    QCOMPARE(rig.wait(queued).error, ErrorKind::Cancelled);
    QVERIFY(rig.indexOfFrame(encode::panicStop()) >= 0);
    QVERIFY(!rig.sim->isMoving(Axis::X)); // no brake ramp
    const MachineStatus& s = rig.ctl->status();
    QVERIFY(s.panic);
    for (const AxisStatus& a : s.axes) {
        QVERIFY(!a.referenced);
        QVERIFY(!a.positionKnown);
    }
    // Jog stays refused until the machine is re-initialised; the line still works.
    rig.ctl->setJogVelocity({{Axis::X, 100}});
    QCOMPARE(rig.jogRefusals->size(), 1);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->refreshStatus(id); }).ok());
    QVERIFY(rig.ctl->status().panic);
}

void TestElabControllerMotion::reference_zeroesPosition_andMarksReferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) {
                   rig.ctl->reference(id, {{Axis::X, -1}, {Axis::Y, 0}, {Axis::Z, 0}});
               })
                .ok());
    QVERIFY(rig.indexOfFrame(bytes("<US>FFFF,0000;0000.")) >= 0);
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    const AxisStatus x = rig.ctl->status().axes.value(Axis::X);
    QVERIFY(x.positionKnown);
    QCOMPARE(x.position, 0);
    QVERIFY(!rig.ctl->status().axes.value(Axis::Y).referenced);
    // An absolute move now works from the referenced origin.
    const qint64 origin = rig.sim->position(Axis::X);
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveAbsolute(id, {{Axis::X, 300}}); }).ok());
    QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(Axis::X), origin + 300, 5000);
    QCOMPARE(rig.ctl->status().axes.value(Axis::X).position, 300);
}

void TestElabControllerMotion::feed_singleAxis_clearPositionThenFeedSteps()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->feed(id, {{Axis::Y, 200}}); }).ok());
    QCOMPARE(rig.framesOut(false),
             (QList<QByteArray>{encode::requestAxeState(), encode::requestMachineState(),
                                bytes("<RS>"), bytes("<SUB>000000C8;")}));
    QTRY_COMPARE_WITH_TIMEOUT(rig.sim->position(Axis::Y), 200, 5000);
}

void TestElabControllerMotion::dc2Stream_xoffXon_noStepLostOrDuplicated()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    // A small buffer so the board says XOFF/XON many times during the stream, drained slowly
    // (400 steps/s, 1.5 s for the 600 steps) so that any host fills it faster than it drains:
    // at the rig's 2 000 steps/s a sanitized build on a slow machine did not, and the board
    // never had to throttle it.
    ParameterSet slowFeed;
    slowFeed.insert("feed-speed", perAxis(400, 400, 400));
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->writeParameters(id, slowFeed, false); }).ok());
    rig.sim->setStreamBuffer(64, 32, 8);
    QVector<AxisVector> steps;
    qint64 expected[3] = {0, 0, 0};
    for (int i = 0; i < 600; ++i) {
        AxisVector s{
            {Axis::X, i % 2 ? 1 : 0}, {Axis::Y, i % 3 ? -1 : 1}, {Axis::Z, i % 5 ? 0 : -1}};
        for (auto it = s.cbegin(); it != s.cend(); ++it)
            expected[it.key().index()] += it.value();
        steps << s;
    }
    const CommandResult r = rig.run([&](RequestId id) { rig.ctl->feedStream(id, steps); }, 20000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QCOMPARE(r.value.toLongLong(), 600);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 20000);
    QCOMPARE(rig.sim->executedStepBytes(), 600);
    QCOMPARE(rig.sim->streamOverflows(), 0);
    QCOMPARE(rig.sim->streamRejected(), 0);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        QCOMPARE(rig.sim->position(a), expected[a.index()]);
        QCOMPARE(rig.ctl->status().axes.value(a).position, expected[a.index()]);
    }
    // The board did throttle the host.
    int xoff = 0;
    int xon = 0;
    for (const TrafficRecord& rec : rig.records(TrafficRecord::Direction::In, true)) {
        xoff += rec.bytes == QByteArray(1, ctrl::XOFF) ? 1 : 0;
        xon += rec.bytes == QByteArray(1, ctrl::XON) ? 1 : 0;
    }
    QVERIFY(xoff >= 2);
    QVERIFY(xon >= 2);
    QVERIFY(rig.indexOfFrame(encode::endOfFeed()) >= 0);
}

void TestElabControllerMotion::feed_multiAxis_streamsStraightLine()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    const CommandResult r = rig.run(
        [&](RequestId id) {
            rig.ctl->feed(id, {{Axis::X, 300}, {Axis::Y, -120}, {Axis::Z, 7}});
        },
        20000);
    QVERIFY2(r.ok(), qPrintable(r.message));
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 20000);
    QCOMPARE(rig.sim->position(Axis::X), 300);
    QCOMPARE(rig.sim->position(Axis::Y), -120);
    QCOMPARE(rig.sim->position(Axis::Z), 7);
    QCOMPARE(rig.sim->executedStepBytes(), 300);
}

void TestElabControllerMotion::velocity_reversalWhileRunning_refused()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 4000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->isMoving(Axis::X), 5000);
    CommandResult r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, -4000}}); });
    QCOMPARE(r.error, ErrorKind::Refused);
    QVERIFY2(r.message.contains("reverse"), qPrintable(r.message));
    // A rate change in the same direction needs no standstill.
    r = rig.run([&](RequestId id) { rig.ctl->velocityMove(id, {{Axis::X, 3500}}); });
    QVERIFY2(r.ok(), qPrintable(r.message));
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
}

void TestElabControllerMotion::limitHitDuringMove_marksAxisUnreferenced()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->reference(id, {{Axis::X, -1}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    rig.sim->setLimitPositions(Axis::X, -100000, rig.sim->position(Axis::X) + 400);
    rig.errors->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->moveRelative(id, {{Axis::X, 3000}}); }).ok());
    QTRY_VERIFY_WITH_TIMEOUT(!rig.ctl->status().axes.value(Axis::X).referenced, 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.errors->isEmpty(), 5000);
    QVERIFY2(rig.errors->last().at(0).toString().contains("limit switch"),
             qPrintable(rig.errors->last().at(0).toString()));
    // Further moves are refused while the switch is active; jog is the way out.
    const CommandResult r = rig.run([&](RequestId id) {
        rig.ctl->moveRelative(id, {{Axis::X, -100}});
    });
    QCOMPARE(r.error, ErrorKind::Refused);
}

void TestElabControllerMotion::dc2Stream_stop_flushesBufferAndEndsFeed()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    QVector<AxisVector> steps(4000, AxisVector{{Axis::X, 1}});
    const RequestId streamId = rig.nextId++;
    rig.ctl->feedStream(streamId, steps);
    QTRY_VERIFY_WITH_TIMEOUT(rig.sim->executedStepBytes() > 100, 5000);
    rig.traffic->clear();
    QVERIFY(rig.run([&](RequestId id) { rig.ctl->stop(id); }).ok());
    const CommandResult streamResult = rig.wait(streamId);
    QCOMPARE(streamResult.error, ErrorKind::Cancelled);
    const int stopAt = rig.indexOfFrame(encode::stopMove());
    const int flushAt = rig.indexOfFrame(encode::flushBuffer());
    const int endAt = rig.indexOfFrame(encode::endOfFeed());
    QVERIFY(stopAt >= 0 && stopAt < flushAt && flushAt < endAt);
    const QList<QByteArray> out = rig.framesOut(true);
    for (int i = stopAt + 1; i < out.size(); ++i)
        QVERIFY(out.at(i).at(0) != ctrl::DC2);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.sim->isMoving(Axis::X), 5000);
    QCOMPARE(rig.sim->streamBuffered(), 0);
    QVERIFY(rig.sim->executedStepBytes() < 4000);
    QTRY_VERIFY_WITH_TIMEOUT(!rig.ctl->status().axes.value(Axis::X).moving, 5000);
    QVERIFY(!rig.ctl->status().axes.value(Axis::X).positionKnown);
}

void TestElabControllerMotion::jog_nak_haltsJogAndSaysWhy()
{
    Rig rig;
    QVERIFY(rig.connectAndSetup());
    rig.sim->forceNak(1);
    rig.ctl->setJogVelocity({{Axis::Z, 300}});
    QTRY_COMPARE_WITH_TIMEOUT(rig.jogRefusals->size(), 1, 5000);
    QVERIFY2(rig.jogRefusals->first().at(0).toString().contains("NAK"),
             qPrintable(rig.jogRefusals->first().at(0).toString()));
    QVERIFY(rig.ctl->jogRamp().isIdle());
    QVERIFY(!rig.sim->isMoving(Axis::Z));
}

STEPDECK_TEST_GUILESS_MAIN(TestElabControllerMotion)
#include "tst_elabcontrollermotion.moc"
