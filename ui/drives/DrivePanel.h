#pragma once
#include "controller/Controller.h"
#include "model/CommandResult.h"
#include "model/MachineStatus.h"
#include <QWidget>
#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;
class QTableView;
class QTableWidget;

namespace stepdeck::ui {

class AxisListBar;
class AxisRowFilter;
class ClosedLoopPanel;
class DriveListModel;
class ElidedLabel;
class MachineContext;
class PositionErrorResetButton;

// The drives of a multi-drive model (Nanotec: one RS485 address per axis) with their
// per-drive status from the poller, and a bus scan listing every drive that answers.
// A drive that stopped answering is marked red: the others keep working.
// The scan runs in chunks of kScanChunk addresses (one operation::kScan each), so it
// shows progress and can be cancelled between chunks; what was found so far stays listed.
class DrivePanel : public QWidget
{
    Q_OBJECT
public:
    enum FoundColumn { FoundAddress, FoundHardware, FoundFirmware, FoundDate, FoundColumnCount };

    explicit DrivePanel(MachineContext* context, QWidget* parent = nullptr);

    // The drives as listed: filtered, in the order shown (DriveListModel's columns).
    QTableView* driveTable() const { return m_drives; }
    AxisListBar* driveBar() const { return m_driveBar; }
    QTableWidget* foundTable() const { return m_found; }
    // Commissioning of closed loop (models with Capabilities::closedLoop; hidden otherwise).
    ClosedLoopPanel* closedLoopPanel() const { return m_closedLoop; }
    static constexpr int kScanChunk = 16;

    QPushButton* scanButton() const { return m_scan; }
    PositionErrorResetButton* resetPositionErrorButton() const { return m_resetError; }
    QPushButton* cancelScanButton() const { return m_cancelScan; }
    QProgressBar* scanProgress() const { return m_progress; }
    bool isScanning() const { return m_scanId != 0; }
    QString scanState() const;
    // Number of drives the status shows as not answering.
    int silentCount() const { return m_silent; }

public Q_SLOTS:
    void scanBus(); // every address the model's bus allows (Capabilities::minBusAddress..max)
    // A partial scan (addresses first..last), e.g. for a quick check of a small bus.
    void scanRange(int first, int last);
    void cancelScan(); // stops after the chunk in flight

private:
    void onStatus(const MachineStatus& status);
    void onResult(const CommandResult& result);
    void showFound(const QVariantList& drives);
    void onLinkState(LinkState state);
    void updateEnabled();
    void showAddressRange(); // the scan button's tooltip names the model's bus addresses
    void scanNextChunk();
    void endScan(const QString& text);

    MachineContext* m_context;
    QTableView* m_drives;
    DriveListModel* m_driveModel;
    AxisRowFilter* m_driveFilter;
    AxisListBar* m_driveBar = nullptr;
    QTableWidget* m_found;
    ClosedLoopPanel* m_closedLoop;
    QPushButton* m_scan;
    QPushButton* m_cancelScan;
    QProgressBar* m_progress;
    ElidedLabel* m_scanState;
    PositionErrorResetButton* m_resetError = nullptr;
    RequestId m_scanId = 0;
    int m_scanFirst = 0;
    int m_scanNext = 0; // first address of the next chunk
    int m_scanLast = 0;
    bool m_scanCancelled = false;
    QVariantList m_foundDrives;
    int m_silent = 0;
};

} // namespace stepdeck::ui
