#pragma once
#include <QLatin1String>
#include <QList>

// The names of the operations only some models offer (Controller::modelOperation,
// ControllerSession::modelOperation): one spelling for the adapters that implement them and the
// GUI and CLI that call them. Arguments and result values are documented by the implementing
// controller's header (NanotecController.h, EmisController.h); which model offers which is
// said by its Capabilities (multiDrive, records, digitalOutputs, storedParameters,
// inputPrograms).
namespace stepdeck::operation {

// Digital outputs of the controller (Capabilities::digitalOutputs).
inline constexpr QLatin1String kSetOutput{"set-output"};
// A reference run with the model's own options (axes at once, switch type).
inline constexpr QLatin1String kReference{"reference"};
// The device's power-on parameter set (Capabilities::storedParameters).
inline constexpr QLatin1String kStoreParameters{"store-parameters"};
inline constexpr QLatin1String kReadStoredParameters{"read-stored-parameters"};
inline constexpr QLatin1String kClearStoredParameters{"clear-stored-parameters"};
// Programs stored per input (Capabilities::inputPrograms).
inline constexpr QLatin1String kWriteInputProgram{"write-input-program"};
inline constexpr QLatin1String kEraseInputProgram{"erase-input-program"};
// The drives on a bus (Capabilities::multiDrive).
inline constexpr QLatin1String kScan{"scan"};
// Stored records and the error memory of a drive (Capabilities::records).
inline constexpr QLatin1String kReadRecord{"read-record"};
inline constexpr QLatin1String kReadAllRecords{"read-all-records"};
inline constexpr QLatin1String kWriteRecord{"write-record"};
inline constexpr QLatin1String kLoadRecord{"load-record"};
inline constexpr QLatin1String kSaveRecord{"save-record"};
inline constexpr QLatin1String kStartRecord{"start-record"};
inline constexpr QLatin1String kReadErrorMemory{"read-error-memory"};
// Position bookkeeping and speed-mode steps of a drive (Nanotec 5.14, 5.18, 7.6-7.8).
inline constexpr QLatin1String kResetPositionError{"reset-position-error"};
inline constexpr QLatin1String kResetPosition{"reset-position"};
inline constexpr QLatin1String kTrigger{"trigger"};
inline constexpr QLatin1String kSpeedStep{"speed-step"};

// The keys of the operations' argument maps (modelOperation(name, {{arg::kAxis, "X"}, ...})):
// one spelling for the callers and the adapters. What each operation takes is documented by
// the implementing controller's header.
namespace arg {
// The drive or axis an operation addresses ("X", "Y", ...): reset-position-error,
// reset-position, trigger, speed-step, the record operations, read-error-memory.
inline constexpr QLatin1String kAxis{"axis"};
// kReference: the axes to reference ("XY"), together or one after the other; their direction
// per axis (map axis name -> -1|1) or the switch type.
inline constexpr QLatin1String kAxes{"axes"};
inline constexpr QLatin1String kSimultaneous{"simultaneous"};
inline constexpr QLatin1String kType{"type"};
inline constexpr QLatin1String kDirection{"direction"};
// kSetOutput: the output's number (1..N) and its new state (bool).
inline constexpr QLatin1String kOutput{"output"};
inline constexpr QLatin1String kOn{"on"};
// kStoreParameters: the ParameterSet to store; skip those the device cannot store.
inline constexpr QLatin1String kParameters{"parameters"};
inline constexpr QLatin1String kSkipUnstorable{"skipUnstorable"};
// kWriteInputProgram / kEraseInputProgram: the input, the program's title and command lines,
// and whether to overwrite a stored program.
inline constexpr QLatin1String kInput{"input"};
inline constexpr QLatin1String kTitle{"title"};
inline constexpr QLatin1String kCommands{"commands"};
inline constexpr QLatin1String kForce{"force"};
// kScan: the address range and the wait per address.
inline constexpr QLatin1String kFirst{"first"};
inline constexpr QLatin1String kLast{"last"};
inline constexpr QLatin1String kTimeoutMs{"timeoutMs"};
// The record operations: the record's number and (kWriteRecord) its values by column.
inline constexpr QLatin1String kRecord{"record"};
inline constexpr QLatin1String kValues{"values"};
// kSpeedStep: up (true) or down.
inline constexpr QLatin1String kUp{"up"};
} // namespace arg

// Every name above (tests: a descriptor names only operations that exist).
inline QList<QLatin1String> all()
{
    return {kSetOutput,
            kReference,
            kStoreParameters,
            kReadStoredParameters,
            kClearStoredParameters,
            kWriteInputProgram,
            kEraseInputProgram,
            kScan,
            kReadRecord,
            kReadAllRecords,
            kWriteRecord,
            kLoadRecord,
            kSaveRecord,
            kStartRecord,
            kReadErrorMemory,
            kResetPositionError,
            kResetPosition,
            kTrigger,
            kSpeedStep};
}

} // namespace stepdeck::operation
