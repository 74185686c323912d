#pragma once
#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class MachineContext;
class MachineMdi;

// The MDI line (issue 31; LinuxCNC's MDI, Candle's and UGS's console line): one G-code line,
// Enter or "Run line" runs it on the machine through MachineMdi (the same check and path as a
// program), Up and Down go through the lines sent before, the modal state the next line starts
// in is shown beside it ("G91 G21 G17 G64 F300"), and then, elided so that it never re-flows
// the layout: what became of the last line. A line that holds at M0 or M6 turns the button into
// Resume. The window's STOP and PANIC abort the line (MachineMdi::abort).
class MdiLine : public QWidget
{
    Q_OBJECT
public:
    explicit MdiLine(MachineContext* context, QWidget* parent = nullptr);

    QLineEdit* lineEdit() const { return m_line; }
    QPushButton* runButton() const { return m_run; }
    QString resultText() const;
    QString shownResultText() const; // as drawn at the current width (elided)
    QString modalText() const;

public Q_SLOTS:
    void run(); // the line as typed; while a line holds at M0 or M6: resume it

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // Up / Down: the history

private:
    void onEnded(quint64 id, bool ok, const QString& message);
    void browseHistory(int step);
    void updateState();

    MachineContext* m_context;
    MachineMdi* m_mdi;
    QLineEdit* m_line;
    QPushButton* m_run;
    QLabel* m_modal;
    ElidedLabel* m_result;
    quint64 m_pending = 0;
    QString m_pendingText;
    int m_historyIndex = -1; // into the history while browsing (-1: the line being typed)
    QString m_typed;         // the line being typed before browsing began
};

} // namespace stepdeck::ui
