// The closed-loop operations of a Nanotec drive (manual 8.1): check, state, enable, and the
// start of the calibration and closed-loop reference runs. The runs themselves are tracked
// by NanotecClosedLoopRun.
#include "NanotecClosedLoop.h"
#include "NanotecController.h"
#include "model/ModelOperations.h"

namespace stepdeck::nanotec {

namespace cl = closedloop;

namespace {
// The motor data of 8.6-8.8 and what the check reads besides (no motion).
struct Reading
{
    const char* parameter;
    QLatin1String key;
};
const Reading kMotorData[] = {
    {"cl-motor-pole-pairs", cl::kMotorPolePairs},
    {"cl-encoder-increments", cl::kEncoderIncrements},
    {"cl-encoder-revolutions", cl::kEncoderRevolutions},
    {"step-angle", cl::kStepAngle},
    {"cl-enable", cl::kEnabled},
    {"encoder-position", cl::kEncoderPosition},
    {"position", cl::kPosition},
};
} // namespace

NanotecClosedLoop::NanotecClosedLoop(NanotecController* controller)
    : QObject(controller), m_ctl(controller)
{}

bool NanotecClosedLoop::isOperation(const QString& name)
{
    return name == cl::kCheck || name == cl::kState || name == cl::kCalibrate ||
           name == cl::kReference || name == cl::kEnable;
}

void NanotecClosedLoop::operation(RequestId id, const QString& name, Axis axis,
                                  const QVariantMap& args)
{
    if (name == cl::kState)
        return m_ctl->finishOk(id, state(axis));
    if (name == cl::kCheck)
        return check(id, axis);
    if (name == cl::kEnable)
        return enable(id, axis, args.value(operation::arg::kOn, true).toBool());
    if (const NanotecClosedLoopRun::Run* run = m_run.find(axis)) {
        return m_ctl->finishError(
            id, ErrorKind::Refused,
            tr("%1 is already in its %2").arg(m_ctl->driveName(axis), m_run.runName(run->kind)));
    }
    if (name == cl::kCalibrate)
        return start(id, axis, Kind::Calibration, 0);
    const int direction = args.value(operation::arg::kDirection, 1).toInt();
    if (direction != 1 && direction != -1) {
        return m_ctl->finishError(
            id, ErrorKind::InvalidValue,
            tr("direction of the closed-loop reference run must be -1 or 1, not %1")
                .arg(direction));
    }
    start(id, axis, Kind::Reference, direction);
}

QString& NanotecClosedLoop::memoryOf(Axis axis, Kind kind)
{
    Memory& m = m_memory[axis];
    return kind == Kind::Calibration ? m.calibration : m.reference;
}

QVariantMap NanotecClosedLoop::state(Axis axis) const
{
    const Memory memory = m_memory.value(axis);
    QVariantMap s{{cl::kAxis, axisName(axis)},
                  {cl::kRun, QString(cl::kRunNone)},
                  {cl::kCalibration, memory.calibration},
                  {cl::kReferenceRun, memory.reference}};
    if (memory.enabled)
        s.insert(cl::kEnabled, *memory.enabled);
    if (const NanotecClosedLoopRun::Run* it = m_run.find(axis)) {
        s.insert(cl::kRun,
                 QString(it->kind == Kind::Calibration ? cl::kRunCalibration : cl::kRunReference));
        s.insert(cl::kElapsedMs, it->clock.elapsed());
        s.insert(cl::kPosition, it->position);
        if (it->encoder)
            s.insert(cl::kEncoderPosition, *it->encoder);
    }
    return s;
}

QStringList NanotecClosedLoop::motorDataProblems(const QVariantMap& data) const
{
    // 8.6-8.8: "Andere Werte haben zur Folge, dass der Regelkreis nicht funktioniert."
    QStringList problems;
    const qint64 pp = data.value(cl::kMotorPolePairs).toLongLong();
    const qint64 inc = data.value(cl::kEncoderIncrements).toLongLong();
    const qint64 rev = data.value(cl::kEncoderRevolutions).toLongLong();
    if (pp != 50 && pp != 100)
        problems << tr("motor pole pairs %1: closed loop works with 50 or 100 only (8.6)").arg(pp);
    if (inc != 1600 && inc != 2000)
        problems
            << tr("encoder increments %1: closed loop works with 1600 or 2000 only (8.7)").arg(inc);
    if (rev != 1)
        problems << tr("encoder revolutions %1: closed loop works with 1 only (8.8)").arg(rev);
    return problems;
}

void NanotecClosedLoop::check(RequestId id, Axis axis)
{
    auto data = std::make_shared<QVariantMap>();
    QList<Step> steps;
    for (const Reading& r : kMotorData) {
        const ParamDef* def = findParam(QString::fromLatin1(r.parameter));
        Q_ASSERT(def);
        // Numbers as the drive reports them; the step angle in degrees ("1.8"), as 'a' says.
        steps << m_ctl->m_parameters.readStep(
            axis, *def,
            [data, def, key = r.key](qint64 wire) {
                data->insert(key, key == cl::kStepAngle ? fromWire(*def, wire)
                                  : key == cl::kEnabled ? QVariant(wire == 1)
                                                        : QVariant(wire));
            },
            nullptr);
    }
    runSteps(steps, [this, id, axis, data](const Failure& f) {
        if (!f.ok())
            return m_ctl->finishWith(id, f);
        m_memory[axis].enabled = data->value(cl::kEnabled).toBool();
        QVariantMap out = state(axis);
        for (auto it = data->cbegin(); it != data->cend(); ++it)
            out.insert(it.key(), it.value());
        out.insert(cl::kProblems, motorDataProblems(*data));
        m_ctl->finishOk(id, out);
    });
}

void NanotecClosedLoop::enable(RequestId id, Axis axis, bool on)
{
    if (on) {
        if (const QString why = m_ctl->m_motion.motionRefusal(axis, false); !why.isEmpty())
            return m_ctl->finishError(id, ErrorKind::Refused, why);
    }
    const ParamDef* def = findParam(QStringLiteral("cl-enable"));
    auto data = std::make_shared<QVariantMap>();
    QList<Step> steps;
    if (on)
        steps << readMotorData(axis, data);
    steps << [this, axis, data, on](const Done& done) {
        const QStringList problems = on ? motorDataProblems(*data) : QStringList();
        if (problems.isEmpty())
            return done({});
        // 8.1 ACHTUNG: wrong motor data can spin the motor up beyond its mechanical limits.
        done({ErrorKind::Refused,
              tr("closed loop not enabled on %1: %2; with wrong motor data the motor can speed up "
                 "beyond its mechanical limits (manual 8.1)")
                  .arg(m_ctl->driveName(axis), problems.join(QStringLiteral("; ")))});
    };
    auto kept = std::make_shared<qint64>(-1);
    steps << m_ctl->m_parameters.writeStep(axis, *def, on ? 1 : 0)
          << m_ctl->m_parameters.readStep(
                 axis, *def, [kept](qint64 v) { *kept = v; }, nullptr);
    runSteps(steps, [this, id, axis, on, kept, def](const Failure& f) {
        if (!f.ok())
            return m_ctl->finishWith(id, f);
        m_memory[axis].enabled = *kept == 1;
        const QVariantMap value{{cl::kAxis, axisName(axis)},
                                {cl::kEnabled, *kept == 1},
                                {cl::kParameter, def->spec.name}};
        if ((*kept == 1) == on)
            return m_ctl->finishOk(id, value);
        m_ctl->finishError(
            id, ErrorKind::VerifyFailed,
            on ? tr("%1 ignored closed loop on: it needs the calibration run (!101) for this motor "
                    "and the closed-loop reference run (!8) since it was switched on (manual 8.1)")
                     .arg(m_ctl->driveName(axis))
               : tr("%1 kept closed loop on").arg(m_ctl->driveName(axis)));
    });
}

void NanotecClosedLoop::start(RequestId id, Axis axis, Kind kind, int direction)
{
    if (const QString why = m_ctl->m_motion.motionRefusal(axis, false); !why.isEmpty())
        return m_ctl->finishError(id, ErrorKind::Refused, why);
    auto data = std::make_shared<QVariantMap>();
    auto mode = std::make_shared<qint64>(1);
    auto modeSet = std::make_shared<bool>(false);
    QList<Step> steps = readMotorData(axis, data);
    steps << m_ctl->m_exchange.exchange(axis, "Z!", sink([mode](qint64 v) { *mode = v; }));
    steps << [this, axis, kind, data](const Done& done) {
        QStringList problems = motorDataProblems(*data);
        if (kind == Kind::Calibration && data->value(cl::kEnabled).toLongLong() == 1)
            problems << tr("closed loop is on; switch it off first");
        if (problems.isEmpty())
            return done({});
        done({ErrorKind::Refused, tr("%1 not started on %2: %3")
                                      .arg(m_run.runName(kind), m_ctl->driveName(axis),
                                           problems.join(QStringLiteral("; ")))});
    };
    const qint64 runMode = kind == Kind::Calibration ? 101 : 8;
    steps << [modeSet](const Done& done) {
        *modeSet = true;
        done({});
    };
    steps << m_ctl->m_exchange.setting(axis, "!" + QByteArray::number(runMode))
          << m_ctl->m_exchange.expectValue(axis, "!", runMode);
    if (kind == Kind::Reference) {
        steps << m_ctl->m_exchange.setting(axis, direction > 0 ? "d1" : "d0")
              << m_ctl->m_exchange.expectValue(axis, "d", direction > 0 ? 1 : 0);
    }
    steps << m_ctl->m_exchange.startRun(axis);
    runSteps(steps, [=](const Failure& f) {
        if (f.ok())
            return m_run.begin(id, axis, kind, restorableMode(*mode));
        if (*modeSet && f.kind != ErrorKind::Cancelled) // not started: the old mode again
            tolerant(m_ctl->m_exchange.setting(
                axis, "!" + QByteArray::number(restorableMode(*mode))))([](const Failure&) {});
        m_ctl->finishWith(id, f);
    });
}

QList<Step> NanotecClosedLoop::readMotorData(Axis axis, std::shared_ptr<QVariantMap> data)
{
    // What a run and closed loop on depend on (8.1): pole pairs, encoder data, closed loop.
    QList<Step> steps;
    for (const Reading& r : kMotorData) {
        if (r.key == cl::kEncoderPosition || r.key == cl::kPosition || r.key == cl::kStepAngle)
            continue;
        steps << m_ctl->m_parameters.readStep(
            axis, *findParam(QString::fromLatin1(r.parameter)),
            [data, key = r.key](qint64 wire) { data->insert(key, wire); }, nullptr);
    }
    return steps;
}

qint64 NanotecClosedLoop::restorableMode(qint64 mode)
{
    return mode >= 1 && mode <= 6 ? mode : 1; // 5.5; a run left in 101 or 8 is not one
}

} // namespace stepdeck::nanotec
