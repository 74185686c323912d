#pragma once
#include "controller/ControllerSession.h"
#include <QWidget>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QPushButton;

namespace stepdeck::ui {

class ElidedLabel;
class LedIndicator;
class MachineContext;

// The connection bar of a machine (issue 19): the machine's name, each controller (its id,
// port and link lamp), the controller the per-controller pages show (a selector, only with
// more than one controller) and one Connect / Disconnect for all of them. It stands in the
// tool bar in place of the single-controller ConnectionBar while a machine is open.
class MachineBar : public QWidget
{
    Q_OBJECT
public:
    static constexpr int kNameChars = 16; // widths in 'M's: the name's least, a port's most
    static constexpr int kPortChars = 12;

    explicit MachineBar(MachineContext* context, QWidget* parent = nullptr);

    // The single-controller connection bar beside this one: exactly one of them is visible,
    // this one while a machine is open.
    void setSingleControllerBar(QWidget* singleController);

    QComboBox* controllerCombo() const { return m_controllers; }
    QPushButton* connectButton() const { return m_connect; }
    LedIndicator* lamp(const QString& controllerId) const;
    ElidedLabel* nameLabel() const { return m_name; }
    QString lampText(const QString& controllerId) const;

public Q_SLOTS:
    void toggleConnection();

private:
    struct Entry
    {
        QString id;
        QString port; // in full, for the tooltip
        LedIndicator* lamp = nullptr;
    };
    void rebuild();
    void showLink(const Entry& entry, LinkState state, const QString& reason);
    void updateButton();

    MachineContext* m_context;
    ElidedLabel* m_name;
    QHBoxLayout* m_lamps;
    QLabel* m_controllerLabel;
    QComboBox* m_controllers;
    QPushButton* m_connect;
    QList<Entry> m_entries;
    QWidget* m_singleBar = nullptr; // the connection bar, shown while no machine is open
};

} // namespace stepdeck::ui
