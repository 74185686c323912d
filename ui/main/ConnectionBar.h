#pragma once
#include "common/LedIndicator.h"
#include "controller/Controller.h"
#include <QElapsedTimer>
#include <QTime>
#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace stepdeck::ui {

class MachineContext;
class PortScanner;

// Model, port (serial ports with description and VID:PID, the simulator, tcp:// or a typed
// path), connect/disconnect, link state and the achieved poll rate.
class ConnectionBar : public QWidget
{
    Q_OBJECT
public:
    explicit ConnectionBar(MachineContext* context, QWidget* parent = nullptr);

    // What the port field names: "sim", a device path or "tcp://HOST:PORT".
    QString portSpec() const;
    void setPortSpec(const QString& spec);
    QString selectedModelId() const;
    void setSelectedModel(const QString& modelId);

    QComboBox* portCombo() const { return m_port; }
    QPushButton* connectButton() const { return m_connect; }
    LedIndicator* linkLamp() const { return m_link; }
    // "Connected", "No reply since 14:03:07", "Link lost", ...: what the lamp says.
    QString linkText() const;
    // Connected, but the device has not answered for several poll intervals: shown at once
    // (amber), before the core declares the link lost.
    bool replyOverdue() const { return m_overdue; }
    int overdueAfterMs() const;

public Q_SLOTS:
    void connectNow();
    void disconnectNow();
    void toggleConnection();

Q_SIGNALS:
    void connectionFailed(const QString& reason);
    void linkTextChanged(const QString& text, bool warning);

private:
    void fillPorts();
    void onLinkState(LinkState state, const QString& reason);
    void onPollRate(double hz);
    void checkReplies();
    void showLink(LedIndicator::State state, const QString& text);

    MachineContext* m_context;
    PortScanner* m_scanner;
    QComboBox* m_model;
    QComboBox* m_port;
    QSpinBox* m_interval;
    QPushButton* m_connect;
    LedIndicator* m_link;
    QLabel* m_rate;
    QTimer* m_replyWatch;
    QElapsedTimer m_sinceReply;
    QTime m_lastReply;
    bool m_overdue = false;
    LinkState m_lastState = LinkState::Disconnected;
};

} // namespace stepdeck::ui
