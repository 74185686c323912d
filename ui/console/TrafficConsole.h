#pragma once
#include "common/ElidedLabel.h"
#include "model/CommandResult.h"
#include "model/Traffic.h"
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QTimer;

namespace stepdeck::ui {

class MachineContext;

// Every byte in and out with timestamps, in the model's notation (E-LAB: control characters
// as mnemonics, "<ESC>S0064,0064;0064."; ASCII protocols as text with \r visible) or in hex;
// direction colours, hide-polls filter, pause, save, and a send line in the same notation.
class TrafficConsole : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kMaxRecords = 20000;

    explicit TrafficConsole(MachineContext* context, QWidget* parent = nullptr);

    QString format(const TrafficRecord& record) const; // one line as shown
    QString formatBytes(const QByteArray& bytes) const;
    bool parseLine(const QString& text, QByteArray* bytes, QString* error) const;
    QString visibleText() const;
    QLineEdit* sendLine() const { return m_send; }
    QCheckBox* hexCheck() const { return m_hex; }
    QCheckBox* hidePollsCheck() const { return m_hidePolls; }
    QCheckBox* pauseCheck() const { return m_pause; }
    QLabel* sendError() const { return m_sendError; }
    bool saveToFile(const QString& path, QString* error) const;
    // Whether the view is refreshed from its timer now: only while the console is on screen.
    bool isRefreshing() const;

public Q_SLOTS:
    void append(const stepdeck::TrafficRecord& record);
    bool sendCurrentLine();
    void clear();
    void saveAs();
    void flush(); // shows what arrived since the last refresh
    // Whether the console's tab is on top (QDockWidget::visibilityChanged); default true.
    void setOnScreen(bool onScreen);

protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    bool accepted(const TrafficRecord& record) const;
    void rerender();
    void updateSendHint(); // the send line's placeholder, in the model's notation
    void appendToView(const QList<TrafficRecord>& records);
    void onResult(const CommandResult& result);
    void updateRefresh(); // the refresh timer runs while the console is on screen

    MachineContext* m_context;
    QList<TrafficRecord> m_records;
    QList<TrafficRecord> m_pending;
    QPlainTextEdit* m_view;
    QCheckBox* m_hex;
    QCheckBox* m_hidePolls;
    QCheckBox* m_pause;
    QLineEdit* m_send;
    QPushButton* m_sendButton;
    ElidedLabel* m_sendError;
    QLabel* m_count;
    QTimer* m_refresh;
    RequestId m_pendingSend = 0;
    bool m_onScreen = true;
};

} // namespace stepdeck::ui
