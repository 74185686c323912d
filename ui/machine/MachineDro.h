#pragma once
#include <QMap>
#include <QWidget>

class QGridLayout;
class QLabel;

namespace stepdeck::machine {
struct MachineAxisStatus;
}

namespace stepdeck::ui {

class DroValueLabel;
class ElidedLabel;
class MachineContext;

// The read-out of a machine (issue 19): its logical axes in their units, from
// Machine::axisStatus -- the device's step count converted back, never a host-side fraction.
// mm and deg with 3 decimals, steps whole; marked by how the position is known (REFERENCED,
// ESTIMATED with "≈", UNKNOWN dimmed, NO LINK for a controller whose link is down) and MOVING
// while it moves. The line below names the controller axis and its count. Nothing widens a
// row: the digits fit their box, the badge is as wide as its longest word, the line elides.
class MachineDro : public QWidget
{
    Q_OBJECT
public:
    explicit MachineDro(MachineContext* context, QWidget* parent = nullptr);

    QString displayedValue(const QString& axis) const; // the digits, for tests
    QString unitText(const QString& axis) const;
    QString stateText(const QString& axis) const;
    QString detailText(const QString& axis) const;
    static QStringList stateWords();

private:
    struct Row
    {
        DroValueLabel* value = nullptr;
        QLabel* state = nullptr;
        ElidedLabel* detail = nullptr;
    };
    void rebuild();
    void refresh();
    void showAxis(const Row& row, const machine::MachineAxisStatus& status, bool linked);
    void setState(const Row& row, const QString& word, const QString& style, bool dim,
                  const QString& tip);

    MachineContext* m_context;
    QGridLayout* m_grid;
    QMap<QString, Row> m_rows;
};

} // namespace stepdeck::ui
