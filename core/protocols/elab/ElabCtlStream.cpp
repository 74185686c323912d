#include "ElabCtlStream.h"
#include "ElabCtlStatusMapper.h"
#include <QCoreApplication>

namespace stepdeck::elab {

QString ElabCtlStream::validate(const QVector<AxisVector>& steps)
{
    for (int i = 0; i < steps.size(); ++i) {
        for (auto it = steps[i].cbegin(); it != steps[i].cend(); ++it) {
            if (!ElabCtlStatusMapper::axes().contains(it.key()))
                return QCoreApplication::translate("stepdeck::elab::ElabController",
                                                   "feed stream step %1: this machine has no "
                                                   "axis %2")
                    .arg(i)
                    .arg(axisName(it.key()));
            if (it.value() < -1 || it.value() > 1)
                return QCoreApplication::translate("stepdeck::elab::ElabController",
                                                   "feed stream step %1: axis %2 moves %3 steps; "
                                                   "a single step is -1, 0 or +1")
                    .arg(i)
                    .arg(axisName(it.key()))
                    .arg(it.value());
        }
    }
    return {};
}

void ElabCtlStream::startSteps(const QVector<AxisVector>& steps)
{
    clear();
    m_steps = steps;
    m_total = steps.size();
    m_active = true;
}

void ElabCtlStream::startLine(const Triple<qint64>& delta)
{
    clear();
    m_line = delta;
    for (qint64 d : delta)
        m_total = qMax(m_total, qAbs(d));
    m_active = true;
}

void ElabCtlStream::startContour(std::shared_ptr<motion::ContourFeed> contour)
{
    clear();
    m_contour = std::move(contour);
    m_active = true;
}

bool ElabCtlStream::atEnd() const
{
    if (m_contour)
        return m_buffered.isEmpty() && m_contour->finished();
    return m_sent >= m_total;
}

void ElabCtlStream::fillFromContour(int want)
{
    if (!m_contour || m_buffered.size() >= want)
        return;
    const int before = int(m_buffered.size());
    m_buffered.resize(want);
    const int n = m_contour->pull(m_buffered.data() + before, want - before);
    m_buffered.resize(before + n);
}

bool ElabCtlStream::waiting()
{
    if (!m_contour)
        return false;
    fillFromContour(kChunkSteps);
    return m_buffered.isEmpty() && !m_contour->finished();
}

void ElabCtlStream::clear()
{
    m_active = false;
    if (m_contour)
        m_contour->setWakeUp({}); // nothing to wake any more
    m_contour.reset();
    m_buffered.clear();
    m_steps.clear();
    m_line = {};
    m_total = 0;
    m_sent = 0;
    pausedByDevice = false;
    chunkInFlight = false;
    stopAsked = false;
    requestId = 0;
}

QList<Axis> ElabCtlStream::axes() const
{
    if (m_contour) // a contour may move any of them
        return ElabCtlStatusMapper::axes();
    QList<Axis> out;
    for (Axis a : ElabCtlStatusMapper::axes()) {
        bool used = m_line[wireIndex(a)] != 0;
        for (int i = 0; !used && i < m_steps.size(); ++i)
            used = m_steps[i].value(a) != 0;
        if (used)
            out << a;
    }
    return out;
}

Triple<int> ElabCtlStream::stepAt(qint64 index) const
{
    Triple<int> step{};
    if (!m_steps.isEmpty()) {
        const AxisVector& v = m_steps.at(int(index));
        for (Axis a : ElabCtlStatusMapper::axes())
            step[wireIndex(a)] = int(v.value(a));
        return step;
    }
    // Axis a steps at i when floor((i+1)*|d|/N) passes an integer: exactly |d| steps in N.
    for (size_t a = 0; a < 3; ++a) {
        const qint64 d = qAbs(m_line[a]);
        if (d == 0)
            continue;
        const qint64 before = index * d / m_total;
        const qint64 after = (index + 1) * d / m_total;
        if (after > before)
            step[a] = m_line[a] > 0 ? 1 : -1;
    }
    return step;
}

QByteArray ElabCtlStream::nextChunk(int maxSteps, Triple<qint64>* delta)
{
    QByteArray out;
    *delta = {};
    if (m_contour) {
        fillFromContour(maxSteps);
        const int n = std::min(maxSteps, int(m_buffered.size()));
        for (int i = 0; i < n; ++i) {
            const motion::StepTick& t = m_buffered.at(i);
            out += encode::feedStep(encodeStepByte(t.step[0], t.step[1], t.step[2]));
            for (size_t a = 0; a < 3; ++a)
                (*delta)[a] += t.step[a];
        }
        m_buffered.remove(0, n);
        m_sent += n;
        return out;
    }
    for (int n = 0; n < maxSteps && m_sent < m_total; ++n, ++m_sent) {
        const Triple<int> s = stepAt(m_sent);
        out += encode::feedStep(encodeStepByte(s[0], s[1], s[2]));
        for (size_t a = 0; a < 3; ++a)
            (*delta)[a] += s[a];
    }
    return out;
}

} // namespace stepdeck::elab
