#pragma once
#include "MachineDescription.h"

namespace stepdeck::machine {

// Where a machine file is wrong: the field as the file spells it ("axes[3].stepsPerUnit",
// empty for the file as a whole), what is wrong with it, and for broken JSON the line and
// column an editor shows.
struct MachineFileError
{
    QString field;
    QString message;
    int line = 0; // 1-based; 0: not a JSON syntax error
    int column = 0;

    // "axes[3].stepsPerUnit: must be a decimal greater than 0 (is -2)"
    QString text() const;
    // Sets *error (when given) to field + message and returns false, for `return report(...)`.
    static bool report(MachineFileError* error, const QString& field, const QString& message);
};

// Reads and validates "stepdeck-machine" files (docs/machines.md). Everything is checked
// before anything is returned, against the registry's models: unknown keys, missing fields,
// wrong types, duplicate names, an axis the controller does not have, a non-finite or
// non-positive stepsPerUnit, min >= max. The first error is reported; nothing is opened.
class MachineFile
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::machine::MachineFile)
public:
    // A controller's setup file (controllers[i].setup) is read and validated against its model,
    // relative to baseDir (load: the file's folder; empty: the current directory).
    static std::optional<MachineDescription> parse(const QByteArray& json, MachineFileError* error,
                                                   const QString& baseDir = {});
    static std::optional<MachineDescription> load(const QString& path, MachineFileError* error);
    // For the editor: the machine as the file describes it whenever its structure reads (JSON,
    // keys, types), even when a value breaks a rule -- *error then names the first such rule
    // and the editor marks it, so a technician can fix a file that does not open. nullopt
    // (and *error) only when the structure itself is broken.
    static std::optional<MachineDescription> parseDraft(const QByteArray& json,
                                                        MachineFileError* error);
    static std::optional<MachineDescription> loadDraft(const QString& path,
                                                       MachineFileError* error);
    // Names each controller's setup file absolute, resolved against the folder of the machine
    // file at machinePath, so that a copy written elsewhere (stepdeck-sim --machine's copy, a
    // file saved to another folder) still finds it.
    static void anchorSetupFiles(MachineDescription* machine, const QString& machinePath);
    // Validates a description built in memory (the GUI's editor) with the same rules.
    static bool validate(const MachineDescription& machine, MachineFileError* error);
    // Atomic (QSaveFile); false with *error set when the file cannot be written.
    static bool save(const MachineDescription& machine, const QString& path, QString* error);

private:
    static std::optional<MachineDescription> readStructure(const QByteArray& json,
                                                           MachineFileError* error);
    static std::optional<QByteArray> read(const QString& path, MachineFileError* error);
    static bool loadSetups(MachineDescription* machine, const QString& baseDir,
                           MachineFileError* error);
};

} // namespace stepdeck::machine
