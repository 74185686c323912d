#pragma once
#include <QStackedWidget>

class QProgressBar;
class QPushButton;
class QTimer;

namespace stepdeck::ui {

class ElidedLabel;

// The Program page's line on the check (issue 29): what the last check said with a Check
// button, or while a check runs longer than a moment its progress with Cancel. One row whose
// height never changes (QStackedWidget sizes to the larger page), so nothing moves when it
// switches. Knows no program: the page says when a check starts and ends.
class ProgramCheckStatus : public QStackedWidget
{
    Q_OBJECT
public:
    static constexpr int kDefaultDelayMs = 300;

    ProgramCheckStatus(ElidedLabel* result, int progressSteps, QWidget* parent = nullptr);

    void started();  // the progress shows once the check took longer than the delay
    void finished(); // back to the result line
    void setProgress(int step);
    bool isShowingProgress() const { return currentIndex() == 1; }
    void setDelay(int ms); // kDefaultDelayMs; tests take 0
    QProgressBar* progressBar() const { return m_progress; }
    QPushButton* cancelButton() const { return m_cancel; }
    QPushButton* checkButton() const { return m_check; }

Q_SIGNALS:
    void checkRequested();
    void cancelRequested();

private:
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    QPushButton* m_check;
    QTimer* m_delay;
};

} // namespace stepdeck::ui
