// A model is its folder and one registry line (docs/architecture.md, "Adding a model"): every
// registered model brings everything the programs take from its descriptor, so a model that is
// only half registered fails here rather than being left out quietly -- by stepdeck-sim, the
// fault soak, the fault matrix, the benchmarks or the German setup pages.
#include "ModelBench.h"
#include "SchemaWords.h"
#include "TestMain.h"
#include "model/ModelOperations.h"
#include "protocols/Registry.h"
#include "sim/TrafficMeter.h"
#include <QRegularExpression>
#include <QtTest>

using namespace stepdeck;

namespace {
constexpr qint64 kShortMove = 200;
constexpr qint64 kLongMove = 20000; // seconds at the soak profiles' speeds

void addModelRows()
{
    QTest::addColumn<QString>("model");
    for (const ModelInfo& m : models())
        QTest::newRow(qPrintable(m.id)) << m.id;
}

// Parameters named by the descriptor that the schema lacks or that cannot be used as named.
QStringList unusableParameters(const ModelInfo& m)
{
    QStringList bad;
    const auto check = [&](const QString& name, bool needWritable, bool needReadable) {
        const ParameterSpec* spec = m.schema.find(name);
        if (!spec || (needWritable && !spec->writable) || (needReadable && !spec->readable))
            bad << name;
    };
    for (const QString& name : m.setupBeforeMotion)
        check(name, true, false);
    for (auto it = m.soak.setup.cbegin(); it != m.soak.setup.cend(); ++it)
        check(it.key(), true, false);
    for (const QString& name : m.soak.readable)
        check(name, false, true);
    return bad;
}

// The moves of one axis the device journaled.
QList<qint64> journaled(Simulator* sim, Axis axis)
{
    QList<qint64> out;
    for (const SimulatedMove& move : sim->acceptedMoves()) {
        if (move.axis == axis)
            out << move.steps;
    }
    return out;
}
} // namespace

class TestModelCompleteness : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void registry_idsUniqueAndPlain();
    void descriptor_everyPartFilledIn_data() { addModelRows(); }
    void descriptor_everyPartFilledIn();
    void controller_builtFromTheDescriptor_agreesWithIt_data() { addModelRows(); }
    void controller_builtFromTheDescriptor_agreesWithIt();
    void simulator_probesSeeWhatTheDeviceDoes_data() { addModelRows(); }
    void simulator_probesSeeWhatTheDeviceDoes();
    void soakProfile_namesOnlyWhatTheModelHas_data() { addModelRows(); }
    void soakProfile_namesOnlyWhatTheModelHas();
    void schemaWords_everyOneTranslated_data() { addModelRows(); }
    void schemaWords_everyOneTranslated();
};

void TestModelCompleteness::registry_idsUniqueAndPlain()
{
    QVERIFY(!models().isEmpty());
    const QRegularExpression plain(QStringLiteral("^[a-z][a-z0-9-]*$"));
    QSet<QString> seen;
    for (const ModelInfo& m : models()) {
        QVERIFY2(plain.match(m.id).hasMatch(), qPrintable(m.id)); // a file key and an option
        QVERIFY2(!seen.contains(m.id), qPrintable(m.id));
        seen.insert(m.id);
        QCOMPARE(findModel(m.id), &m);
    }
    QCOMPARE(modelIds().size(), models().size());
}

void TestModelCompleteness::descriptor_everyPartFilledIn()
{
    QFETCH(QString, model);
    const ModelInfo& m = *findModel(model);
    QVERIFY(!m.displayName.isEmpty());
    QVERIFY(m.line.baudRate > 0);
    QVERIFY(!m.capabilities.axes.isEmpty());
    QVERIFY(m.createController);
    QVERIFY(m.createSimulator);
    QVERIFY(m.scenario.apply);
    QVERIFY(m.soak.prepare);
    QVERIFY(m.presentation.formatTraffic);
    QVERIFY(m.presentation.parseTraffic);
    if (m.capabilities.inputPrograms)
        QVERIFY(m.presentation.checkProgramCommand);
    if (m.capabilities.multiDrive) {
        QVERIFY(m.capabilities.minBusAddress > 0);
        QVERIFY(m.capabilities.minBusAddress <= m.capabilities.maxBusAddress);
    }
    // The benchmarks' stream figures need a meter wherever there is a stream.
    QCOMPARE(m.streamBench.supported(), m.capabilities.has(MotionMode::FeedStream));
    if (m.streamBench.supported()) {
        const std::unique_ptr<TrafficMeter> meter = m.streamBench.createMeter();
        QVERIFY(meter);
        QCOMPARE(meter->stepBytes(), qint64(0));
        QCOMPARE(meter->panicSeenNs(), qint64(-1));
    }
    // Its own logging category, declared in its folder.
    QVERIFY(m.logging);
    QVERIFY2(QByteArray(m.logging().categoryName()).startsWith("stepdeck."),
             m.logging().categoryName());
    QVERIFY2(unusableParameters(m).isEmpty(), qPrintable(unusableParameters(m).join(", ")));
}

void TestModelCompleteness::controller_builtFromTheDescriptor_agreesWithIt()
{
    QFETCH(QString, model);
    test::ModelBench b(findModel(model), 500);
    QVERIFY(b.ctl);
    QVERIFY(b.sim);
    const Capabilities caps = b.ctl->capabilities();
    QCOMPARE(caps.axes, b.info->capabilities.axes); // the default machine
    QCOMPARE(caps.stopCommand, b.info->capabilities.stopCommand);
    QCOMPARE(caps.multiDrive, b.info->capabilities.multiDrive);
    QStringList own, described;
    const ParameterSchema schema = b.ctl->schema();
    for (const ParameterSpec& s : schema.specs())
        own << s.name;
    for (const ParameterSpec& s : b.info->schema.specs())
        described << s.name;
    QCOMPARE(own, described);
    // A scenario without options leaves a fresh simulator as it was.
    std::unique_ptr<Simulator> fresh(b.info->createSimulator(SimulatorOptions{}));
    QString error;
    QVERIFY2(b.info->scenario.apply(SimulatorScenario{}, fresh.get(), &error), qPrintable(error));
    QVERIFY(fresh->standingStill());
}

// The probes the soak and the fault matrix ask (isMoving, position, acceptedMoves,
// emergencyStop, isStopFrame) follow a move the controller sends, on the first axis.
void TestModelCompleteness::simulator_probesSeeWhatTheDeviceDoes()
{
    QFETCH(QString, model);
    test::ModelBench b(findModel(model), 500);
    const ModelInfo& m = *b.info;
    const Axis axis = m.capabilities.axes.first();
    if (m.soak.prepare) // its absence fails descriptor_everyPartFilledIn
        m.soak.prepare(b.sim.get());
    QVERIFY(b.sim->standingStill());
    QVERIFY(!b.sim->isMoving(axis));
    QVERIFY(b.run([&](RequestId id) { b.ctl->openLink(id); }, 5000).ok());
    if (!m.soak.setup.isEmpty()) {
        const CommandResult setup =
            b.run([&](RequestId id) { b.ctl->writeParameters(id, m.soak.setup, false); }, 5000);
        QVERIFY2(setup.ok(), qPrintable(setup.message));
    }
    b.sim->clearReceivedFrames();
    // Models that report positions only after a command are sent where they stand first.
    const auto moveBy = [&](qint64 steps) {
        return [&, steps](RequestId id) {
            if (m.soak.anchorPositions)
                b.ctl->moveAbsolute(id, {{axis, b.sim->position(axis) + steps}});
            else
                b.ctl->moveRelative(id, {{axis, steps}});
        };
    };

    const qint64 before = b.sim->position(axis);
    const int journalBefore = int(journaled(b.sim.get(), axis).size());
    const CommandResult moved = b.run(moveBy(kShortMove), 10000);
    QVERIFY2(moved.ok(), qPrintable(moved.message));
    QTRY_VERIFY_WITH_TIMEOUT(b.sim->standingStill(), 10000);
    QCOMPARE(b.sim->position(axis), before + kShortMove);
    QCOMPARE(journaled(b.sim.get(), axis).mid(journalBefore), QList<qint64>{kShortMove});
    QTRY_VERIFY_WITH_TIMEOUT(!b.ctl->status().anyMoving(), 5000); // the host saw it arrive

    // A long move: the device moves until its own emergency stop.
    moveBy(kLongMove)(++b.nextId); // not waited for: some models finish on arrival only
    QTRY_VERIFY_WITH_TIMEOUT(b.sim->isMoving(axis), 5000);
    QVERIFY(!b.sim->standingStill());
    b.sim->emergencyStop();
    QTRY_VERIFY_WITH_TIMEOUT(b.sim->standingStill(), 5000);
    QVERIFY(!b.sim->isMoving(axis));
    QVERIFY(b.sim->position(axis) < before + kShortMove + kLongMove);

    // The host's stop, as the device recognises it among its frames (the fault matrix asks).
    if (m.capabilities.stopCommand) {
        b.sim->clearReceivedFrames();
        b.run([&](RequestId id) { b.ctl->stop(id); }, 5000);
        bool stopSeen = false;
        for (const QByteArray& frame : b.sim->receivedFrames())
            stopSeen = stopSeen || b.sim->isStopFrame(frame);
        QVERIFY(stopSeen);
    }
}

void TestModelCompleteness::soakProfile_namesOnlyWhatTheModelHas()
{
    QFETCH(QString, model);
    const ModelInfo& m = *findModel(model);
    for (const QString& name : m.soak.recovery) {
        bool known = false;
        for (QLatin1String op : operation::all())
            known = known || name == op;
        QVERIFY2(known, qPrintable(name));
    }
    QCOMPARE(!m.soak.simulatorAddresses.isEmpty(), m.capabilities.multiDrive);
    for (int address : m.soak.simulatorAddresses) {
        QVERIFY(address >= m.capabilities.minBusAddress);
        QVERIFY(address <= m.capabilities.maxBusAddress);
    }
    for (auto it = m.soak.setup.cbegin(); it != m.soak.setup.cend(); ++it) {
        for (Axis a : it.value().perAxis.keys())
            QVERIFY2(m.capabilities.axes.contains(a), qPrintable(it.key()));
    }
    const QString invalid = m.schema.validate(m.soak.setup, m.capabilities.axes);
    QVERIFY2(invalid.isEmpty(), qPrintable(invalid));
}

void TestModelCompleteness::schemaWords_everyOneTranslated()
{
    QFETCH(QString, model);
    const QSet<QString> translated = test::translatedSchemaWords(
        QStringLiteral(STEPDECK_SOURCE_DIR "/translations/stepdeck_de.ts"));
    QVERIFY(translated.size() > 200);
    const QStringList missing = test::untranslatedSchemaWords(*findModel(model), translated);
    QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QStringLiteral(" | "))));
}

STEPDECK_TEST_GUILESS_MAIN(TestModelCompleteness)
#include "tst_modelcompleteness.moc"
