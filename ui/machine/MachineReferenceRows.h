#pragma once
#include <QMap>
#include <QStringList>
#include <QWidget>

class QGridLayout;
class QLabel;
class QPushButton;

namespace stepdeck::ui {

class LedIndicator;
class MachineContext;

// The referencing rows of an open machine (issue 19): every logical axis with the direction
// and order its machine file gives (read-only: the file is what Machine::reference follows,
// so an editable field here would promise a run that does not happen), its referenced lamp
// from Machine::axisStatus and a button that references that axis alone.
class MachineReferenceRows : public QWidget
{
    Q_OBJECT
public:
    explicit MachineReferenceRows(MachineContext* context, QWidget* parent = nullptr);

    QStringList axisNames() const { return m_rows.keys(); }
    QString directionText(const QString& axis) const;
    QString orderText(const QString& axis) const;
    QPushButton* runButton(const QString& axis) const;
    // Buttons enabled only while connected and no run is under way (ReferencePanel decides).
    void setRunsEnabled(bool enabled);
    // The lamps of the axes `running` show "referencing"; the others their state.
    void setRunningAxes(const QStringList& running);

Q_SIGNALS:
    void referenceRequested(const QStringList& axes);

private:
    struct Row
    {
        QLabel* direction = nullptr;
        QLabel* order = nullptr;
        LedIndicator* led = nullptr;
        QPushButton* run = nullptr;
    };
    void rebuild();
    void refresh();

    MachineContext* m_context;
    QGridLayout* m_grid;
    QMap<QString, Row> m_rows;
    QStringList m_running;
};

} // namespace stepdeck::ui
