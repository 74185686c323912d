#pragma once
#include "controller/Controller.h"
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace stepdeck::ui {

class MachineContext;

// The drives of a multi-drive model (Nanotec: one RS485 address per axis) with their
// per-drive status from the poller, and a bus scan listing every drive that answers.
// A drive that stopped answering is marked red: the others keep working.
class DrivePanel : public QWidget
{
    Q_OBJECT
public:
    enum Column { Address, Axes, Responding, Firmware, Detail, ColumnCount };
    enum FoundColumn { FoundAddress, FoundHardware, FoundFirmware, FoundDate, FoundColumnCount };

    explicit DrivePanel(MachineContext* context, QWidget* parent = nullptr);

    QTableWidget* driveTable() const { return m_drives; }
    QTableWidget* foundTable() const { return m_found; }
    QPushButton* scanButton() const { return m_scan; }
    QString scanState() const;
    // Number of drives the status shows as not answering.
    int silentCount() const { return m_silent; }

public Q_SLOTS:
    void scanBus();
    // A partial scan (addresses first..last), e.g. for a quick check of a small bus.
    void scanRange(int first, int last);

private:
    void onStatus(const MachineStatus& status);
    void onResult(const CommandResult& result);
    void showFound(const QVariantList& drives);
    void onLinkState(LinkState state);
    void updateEnabled();

    MachineContext* m_context;
    QTableWidget* m_drives;
    QTableWidget* m_found;
    QPushButton* m_scan;
    QLabel* m_scanState;
    RequestId m_scanId = 0;
    int m_silent = 0;
};

} // namespace stepdeck::ui
