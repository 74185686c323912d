#include "KeyboardJog.h"
#include "common/TextFieldFocus.h"
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QStyleHints>
#include <QTextEdit>

namespace stepdeck::ui {

namespace {
struct KeySlot
{
    int key;
    JogSlot slot;
    double sign;
};
constexpr KeySlot kKeys[] = {
    {Qt::Key_Right, JogSlot::PadHorizontal, 1}, {Qt::Key_Left, JogSlot::PadHorizontal, -1},
    {Qt::Key_Up, JogSlot::PadVertical, 1},      {Qt::Key_Down, JogSlot::PadVertical, -1},
    {Qt::Key_PageUp, JogSlot::ZStick, 1},       {Qt::Key_PageDown, JogSlot::ZStick, -1},
    {Qt::Key_Home, JogSlot::OtherStick, 1},     {Qt::Key_End, JogSlot::OtherStick, -1},
};

const KeySlot* lookup(int key)
{
    for (const KeySlot& k : kKeys) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}
} // namespace

KeyboardJog::KeyboardJog(QWidget* window, QObject* parent)
    : JogInputSource(parent), m_window(window)
{
    m_clock.start();
    connect(qApp, &QApplication::focusChanged, this, [this] {
        releaseAll();
        checkPaused();
    });
    connect(qApp, &QGuiApplication::applicationStateChanged, this,
            [this](Qt::ApplicationState state) {
                if (state != Qt::ApplicationActive)
                    releaseAll();
                checkPaused();
            });
}

KeyboardJog::~KeyboardJog()
{
    if (m_enabled)
        qApp->removeEventFilter(this);
}

void KeyboardJog::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    if (enabled) {
        qApp->installEventFilter(this);
    } else {
        qApp->removeEventFilter(this);
        releaseAll();
    }
}

void KeyboardJog::setSpeedFraction(double fraction)
{
    m_fraction = qBound(0.01, fraction, 1.0);
    if (!m_held.isEmpty())
        Q_EMIT changed();
}

void KeyboardJog::setProofWindows(int firstRepeatMs, int repeatMs)
{
    m_firstWindowMs = qMax(0, firstRepeatMs);
    m_repeatWindowMs = qMax(0, repeatMs);
}

int KeyboardJog::firstRepeatWindowMs() const
{
    return m_firstWindowMs > 0 ? m_firstWindowMs : kFirstRepeatWindowMs;
}

int KeyboardJog::repeatWindowMs() const
{
    if (m_repeatWindowMs > 0)
        return m_repeatWindowMs;
    const int rate = QGuiApplication::styleHints()->keyboardAutoRepeatRate(); // per second
    const int interval = rate > 0 ? 1000 / rate : 100;
    return qMax(kMinRepeatWindowMs, 3 * interval);
}

void KeyboardJog::releaseAll()
{
    if (m_held.isEmpty())
        return;
    m_held.clear();
    Q_EMIT changed();
}

bool KeyboardJog::windowActive() const
{
    return m_window && m_window->isActiveWindow();
}

bool KeyboardJog::textFieldHasFocus() const
{
    return ui::textFieldHasFocus();
}

bool KeyboardJog::accepts() const
{
    return windowActive() && !textFieldHasFocus();
}

void KeyboardJog::checkPaused()
{
    const bool paused = !accepts();
    if (paused != m_paused) {
        m_paused = paused;
        Q_EMIT pausedChanged(paused);
    }
}

bool KeyboardJog::isFresh(const HeldKey& key, qint64 now) const
{
    return now - key.provenMs <= (key.repeating ? repeatWindowMs() : firstRepeatWindowMs());
}

SlotVelocities KeyboardJog::heldDeflection()
{
    const qint64 now = m_clock.elapsed();
    SlotVelocities fractions;
    for (auto it = m_held.cbegin(); it != m_held.cend(); ++it) {
        const KeySlot* k = lookup(it.key());
        if (k && isFresh(it.value(), now))
            fractions[k->slot] += k->sign * m_fraction;
    }
    return fractions;
}

bool KeyboardJog::handleKey(QKeyEvent* key)
{
    const KeySlot* k = lookup(key->key());
    if (!k || key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
        return false;
    const bool press = key->type() == QEvent::KeyPress;
    const auto held = m_held.find(k->key);
    if (press && held == m_held.end() && !accepts())
        return false; // typed into a text field, or not our window
    if (!press && held == m_held.end())
        return false;
    if (key->isAutoRepeat()) {
        // Proof that the key is still held. A repeat of a key not held (released by a focus
        // change, STOP, or pressed elsewhere) starts nothing.
        if (press && held != m_held.end()) {
            const bool wasFresh = isFresh(*held, m_clock.elapsed());
            held->provenMs = m_clock.elapsed();
            held->repeating = true;
            if (!wasFresh)
                Q_EMIT changed(); // revived
        }
        return true;
    }
    if (press) {
        m_held.insert(k->key, HeldKey{m_clock.elapsed(), false});
    } else {
        m_held.erase(held);
    }
    Q_EMIT changed();
    return true;
}

bool KeyboardJog::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
        if (handleKey(static_cast<QKeyEvent*>(event)))
            return true; // consumed, auto-repeat included
        break;
    case QEvent::WindowDeactivate:
        if (watched == m_window)
            releaseAll();
        break;
    default:
        break;
    }
    return JogInputSource::eventFilter(watched, event);
}

QString KeyboardJog::keyLegend(const QMap<JogSlot, QString>& slotLabels)
{
    QStringList parts;
    if (slotLabels.contains(JogSlot::PadHorizontal))
        parts << tr("\u2190/\u2192 %1").arg(slotLabels.value(JogSlot::PadHorizontal));
    if (slotLabels.contains(JogSlot::PadVertical))
        parts << tr("\u2193/\u2191 %1").arg(slotLabels.value(JogSlot::PadVertical));
    if (slotLabels.contains(JogSlot::ZStick))
        parts << tr("Page Down/Up %1").arg(slotLabels.value(JogSlot::ZStick));
    if (slotLabels.contains(JogSlot::OtherStick))
        parts << tr("End/Home %1").arg(slotLabels.value(JogSlot::OtherStick));
    return parts.join(QStringLiteral(", "));
}

} // namespace stepdeck::ui
