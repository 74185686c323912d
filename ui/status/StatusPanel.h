#pragma once
#include "model/MachineStatus.h"
#include <QWidget>

class QGridLayout;
class QLabel;
class QProgressBar;
class QScrollArea;
class QVBoxLayout;

namespace stepdeck::ui {

class AxisStatusList;
class DigitalIoGroup;
class LedIndicator;
class MachineContext;
class RawWordView;

// The poller made visible: the normalised machine and axis flags every model maps to, the
// model's raw words with the manual's bit names, temperature (warning before the 50 degC
// shutdown), the start button, the controller's digital inputs and outputs (outputs
// switchable), its firmware, and the comm-fault and resync counters.
class StatusPanel : public QWidget
{
    Q_OBJECT
public:
    static constexpr double kTemperatureWarningC = 45.0;
    static constexpr double kTemperatureLimitC = 50.0;
    // More axes than this: a filtered list instead of the lamp grid (issue 32, step 5).
    static constexpr int kGridAxes = 4;

    explicit StatusPanel(MachineContext* context, QWidget* parent = nullptr);

    LedIndicator* machineLamp(const QString& key) const { return m_machine.value(key); }
    RawWordView* rawWord(const QString& key) const;
    AxisStatusList* axisList() const { return m_axisList; } // nullptr: the lamp grid
    QString temperatureText() const;
    QString countersText() const;
    QString temperatureNote() const;
    DigitalIoGroup* digitalIo() const { return m_io; } // nullptr: the model has no I/O
    QString firmwareText() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void rebuild();
    QWidget* buildMachineGroup();
    // The lamp grid or, above kGridAxes axes, the list; then the model's raw words.
    void addAxesAndWords(QVBoxLayout* v, QWidget* inner);
    void showDrives(const MachineStatus& s);
    void arrangeColumns(); // lamps in two columns where they fit, else one
    QWidget* buildAxesGroup();
    QWidget* buildTemperatureGroup();
    void onStatus(const MachineStatus& status);
    void updateTemperature(const MachineStatus& status);

    MachineContext* m_context;
    QVBoxLayout* m_body;
    QScrollArea* m_content = nullptr;
    QWidget* m_viewport = nullptr; // m_content's viewport, watched for resizes
    QMap<QString, LedIndicator*> m_machine;
    QList<LedIndicator*> m_machineOrder;
    QWidget* m_machineGroup = nullptr;
    QGridLayout* m_machineGrid = nullptr;
    int m_machineColumns = 0;
    QMap<Axis, QMap<QString, LedIndicator*>> m_axes;
    AxisStatusList* m_axisList = nullptr;
    QList<RawWordView*> m_words;
    QLabel* m_genericRaw = nullptr;
    QLabel* m_temperature = nullptr;
    QProgressBar* m_temperatureBar = nullptr;
    QLabel* m_temperatureNote = nullptr;
    QLabel* m_counters = nullptr;
    QLabel* m_drives = nullptr;
    QLabel* m_firmware = nullptr;
    DigitalIoGroup* m_io = nullptr;
};

} // namespace stepdeck::ui
