#pragma once
#include "jog/JogInputSource.h"
#include <QPointer>
#include <QSet>

class QWidget;

namespace stepdeck::ui {

// Keyboard jog: arrows for X/Y, Page Up/Down for Z, Home/End for U. Installed as an
// application event filter while enabled. Auto-repeat is ignored (it would neither stutter nor
// extend the motion); focus changes and window deactivation release every key at once, since
// a key-up that goes to another window would otherwise never arrive (a known runaway).
// Keys typed into text fields and spin boxes are left alone.
class KeyboardJog : public JogInputSource
{
    Q_OBJECT
public:
    explicit KeyboardJog(QWidget* window, QObject* parent = nullptr);
    ~KeyboardJog() override;

    QString sourceName() const override { return tr("Keyboard"); }
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void setSpeedFraction(double fraction); // share of the axis' max jog speed
    double speedFraction() const { return m_fraction; }
    bool isJogging() const { return !m_held.isEmpty(); }

public Q_SLOTS:
    void releaseAll();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool accepts() const; // main window active and no text input focused
    void publish();

    QPointer<QWidget> m_window;
    bool m_enabled = false;
    double m_fraction = 0.5;
    QSet<int> m_held;
};

} // namespace stepdeck::ui
