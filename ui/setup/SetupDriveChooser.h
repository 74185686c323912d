#pragma once
#include "model/Axis.h"
#include <QWidget>

class QLabel;
class QLineEdit;

namespace stepdeck::ui {

class MachineContext;

// Which drives' columns the setup page shows on a bus of more drives than fit side by side
// (issue 32, step 5; Nanotec's own tools set up one drive at a time): the first kColumns
// drives whose name or bus address contains the typed text. The page's Read fills them, and
// its Write, Write all and Save take the drives shown and the global values.
class SetupDriveChooser : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kColumns = 4; // per-axis columns that fit 1366x768 with their labels

    explicit SetupDriveChooser(MachineContext* context, QWidget* parent = nullptr);

    // Every axis of the controller (once per connection); shows the first kColumns.
    void setAxes(const QList<Axis>& axes);
    QList<Axis> shownAxes() const { return m_shown; }
    QLineEdit* filterEdit() const { return m_edit; }
    QString shownText() const;
    // Back to the drives shown before (the page refused the change: unwritten edits).
    void revert();

    // The first kColumns of `axes` whose name or address contains `text` (case-insensitive).
    static QList<Axis> choose(const QList<Axis>& axes, const QStringList& names,
                              const QList<int>& addresses, const QString& text);

Q_SIGNALS:
    void shownAxesChanged(const QList<Axis>& axes);

private:
    void onText(const QString& text);
    void showChoice();

    MachineContext* m_context;
    QList<Axis> m_axes;
    QList<Axis> m_shown;
    QString m_shownFor;                   // the filter text m_shown was chosen for
    QPair<QList<Axis>, QString> m_before; // what revert() goes back to
    QLineEdit* m_edit;
    QLabel* m_label;
};

} // namespace stepdeck::ui
