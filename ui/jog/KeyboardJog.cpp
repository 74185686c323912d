#include "KeyboardJog.h"
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>

namespace stepdeck::ui {

namespace {
struct KeyAxis
{
    int key;
    Axis axis;
    double sign;
};
constexpr KeyAxis kKeys[] = {
    {Qt::Key_Right, Axis::X, 1}, {Qt::Key_Left, Axis::X, -1},  {Qt::Key_Up, Axis::Y, 1},
    {Qt::Key_Down, Axis::Y, -1}, {Qt::Key_PageUp, Axis::Z, 1}, {Qt::Key_PageDown, Axis::Z, -1},
    {Qt::Key_Home, Axis::U, 1},  {Qt::Key_End, Axis::U, -1},
};

const KeyAxis* lookup(int key)
{
    for (const KeyAxis& k : kKeys) {
        if (k.key == key)
            return &k;
    }
    return nullptr;
}
} // namespace

KeyboardJog::KeyboardJog(QWidget* window, QObject* parent)
    : JogInputSource(parent), m_window(window)
{
    connect(qApp, &QApplication::focusChanged, this, &KeyboardJog::releaseAll);
    connect(qApp, &QGuiApplication::applicationStateChanged, this,
            [this](Qt::ApplicationState state) {
                if (state != Qt::ApplicationActive)
                    releaseAll();
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
        publish();
}

void KeyboardJog::releaseAll()
{
    if (m_held.isEmpty())
        return;
    m_held.clear();
    publish();
}

bool KeyboardJog::accepts() const
{
    if (!m_window || !m_window->isActiveWindow())
        return false;
    QWidget* focus = QApplication::focusWidget();
    if (qobject_cast<QLineEdit*>(focus) || qobject_cast<QAbstractSpinBox*>(focus) ||
        qobject_cast<QPlainTextEdit*>(focus) || qobject_cast<QTextEdit*>(focus))
        return false;
    if (auto* combo = qobject_cast<QComboBox*>(focus))
        return !combo->isEditable();
    return true;
}

bool KeyboardJog::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::KeyPress:
    case QEvent::KeyRelease: {
        auto* key = static_cast<QKeyEvent*>(event);
        const KeyAxis* k = lookup(key->key());
        if (!k || key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
            break;
        const bool press = event->type() == QEvent::KeyPress;
        if (press && !accepts())
            break;
        if (!press && !m_held.contains(k->key))
            break;
        if (!key->isAutoRepeat()) {
            if (press)
                m_held.insert(k->key);
            else
                m_held.remove(k->key);
            publish();
        }
        return true; // consumed, auto-repeat included
    }
    case QEvent::WindowDeactivate:
        if (watched == m_window)
            releaseAll();
        break;
    default:
        break;
    }
    return JogInputSource::eventFilter(watched, event);
}

void KeyboardJog::publish()
{
    AxisVelocities fractions;
    for (const KeyAxis& k : kKeys) {
        if (m_held.contains(k.key))
            fractions[k.axis] += k.sign * m_fraction;
    }
    Q_EMIT deflectionChanged(fractions);
}

} // namespace stepdeck::ui
