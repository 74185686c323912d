#pragma once
#include "jog/JogInputSource.h"
#include <QElapsedTimer>
#include <QHash>
#include <QPointer>

class QKeyEvent;
class QWidget;

namespace stepdeck::ui {

// Keyboard jog: arrows for X/Y, Page Up/Down for Z, Home/End for U (the jog slots: with a
// machine open the machine axes on the pad and the sticks, JogAxisMap). Installed as an
// application event filter while enabled. Keys typed into text fields and spin boxes are left
// alone (the jog panel says keyboard jog is paused meanwhile).
//
// Proof of holding: a held key proves itself by its auto-repeat. The platform sends the first
// repeat only after its repeat delay (X11 default 660 ms, GNOME 500 ms; Qt 6.4 cannot query
// it), longer than the core's 300 ms lease, so the press itself counts as proof for
// firstRepeatWindowMs() (kFirstRepeatWindowMs, a documented bound above those defaults);
// after that each repeat counts for repeatWindowMs() (three repeat intervals from
// QStyleHints::keyboardAutoRepeatRate(), at least kMinRepeatWindowMs). A key whose proof is
// older contributes zero: a key-up that never arrives stops the axis within those bounds plus
// one renewal (JogController::kRenewMs) and the core's ramp. A repeat that arrives later
// revives the key (it is evidently held), so a platform with a longer delay only sees a dip.
// X11 repeats only the key pressed last: with two keys held, the earlier one stops after its
// window (use the pad or a gamepad for diagonals).
// Focus changes, window deactivation, STOP and PANIC latch every held key: it moves nothing
// again until it has been released and pressed anew (its repeats are ignored meanwhile).
class KeyboardJog : public JogInputSource
{
    Q_OBJECT
public:
    static constexpr int kFirstRepeatWindowMs = 800;
    static constexpr int kMinRepeatWindowMs = 200;

    explicit KeyboardJog(QWidget* window, QObject* parent = nullptr);
    ~KeyboardJog() override;

    QString sourceName() const override { return tr("Keyboard"); }
    SlotVelocities heldDeflection() override;
    void latch() override { releaseAll(); }

    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    void setSpeedFraction(double fraction); // share of the axis' max jog speed
    double speedFraction() const { return m_fraction; }
    bool isJogging() const { return !m_held.isEmpty(); }
    // Keys typed now would go to a text field (or the window is not active): no jog.
    bool isPaused() const { return !accepts(); }
    bool windowActive() const;
    bool textFieldHasFocus() const;
    // The proof windows (tests shorten them; 0 restores the default).
    void setProofWindows(int firstRepeatMs, int repeatMs);
    int firstRepeatWindowMs() const;
    int repeatWindowMs() const;
    // What the panel shows for the jog slots (JogAxisMap) and the machine axis each one moves:
    // "←/→ X, ↓/↑ Y, Page Down/Up Z, End/Home A".
    static QString keyLegend(const QMap<JogSlot, QString>& slotLabels);

public Q_SLOTS:
    void releaseAll();

Q_SIGNALS:
    void pausedChanged(bool paused);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct HeldKey
    {
        qint64 provenMs = 0;    // time of the press or of the latest auto-repeat
        bool repeating = false; // at least one auto-repeat arrived
    };
    bool accepts() const; // main window active and no text input focused
    bool handleKey(QKeyEvent* key);
    bool isFresh(const HeldKey& key, qint64 now) const;
    void checkPaused();

    QPointer<QWidget> m_window;
    bool m_enabled = false;
    double m_fraction = 0.5;
    QHash<int, HeldKey> m_held;
    QElapsedTimer m_clock;
    int m_firstWindowMs = 0;
    int m_repeatWindowMs = 0;
    bool m_paused = true;
};

} // namespace stepdeck::ui
