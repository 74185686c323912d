#include "MachineFile.h"
#include "model/NearestName.h"
#include "model/ParameterFile.h"
#include "protocols/Registry.h"
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>
#include <cmath>

namespace stepdeck::machine {

namespace {

// The structural half of reading a file: keys, presence and JSON types, with the field path
// of every error. The rules about values (ranges, references, models) are
// MachineFile::validate's, shared with the GUI editor.
class Reader
{
public:
    explicit Reader(MachineFileError* error) : m_error(error) {}

    bool readTop(const QJsonObject& top, MachineDescription* d);

private:
    bool fail(const QString& field, const QString& message)
    {
        return MachineFileError::report(m_error, field, message);
    }
    bool onlyKeys(const QJsonObject& o, const QString& path, const QStringList& allowed);
    bool string(const QJsonObject& o, const QString& path, const char* key, QString* out,
                bool required = true);
    bool number(const QJsonObject& o, const QString& path, const char* key,
                std::optional<double>* out);
    bool readController(const QJsonValue& v, const QString& path, MachineController* c);
    bool readAddresses(const QJsonValue& v, const QString& path, MachineController* c);
    bool readAddressesV1(const QJsonValue& v, const QString& path, MachineController* c);
    bool readAxis(const QJsonValue& v, const QString& path, MachineAxis* a);
    bool readAxisValues(const QJsonObject& o, const QString& path, MachineAxis* a);
    bool readReference(const QJsonValue& v, const QString& path, MachineAxis* a);
    bool readSoftLimits(const QJsonValue& v, const QString& path, MachineAxis* a);
    bool readSpindle(const QJsonValue& v, MachineSpindle* s);
    bool readLimits(const QJsonObject& top, MachineDescription* d);
    bool readToolLength(const QJsonObject& top, MachineDescription* d);

    MachineFileError* m_error;
    int m_version = 0;
    const QList<MachineController>* m_controllers = nullptr; // read before the axes
};

QString join(const QString& path, const char* key)
{
    return path.isEmpty() ? QString::fromLatin1(key) : path + QLatin1Char('.') + key;
}

bool isWhole(double v)
{
    return std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e9;
}

bool Reader::onlyKeys(const QJsonObject& o, const QString& path, const QStringList& allowed)
{
    for (const QString& key : o.keys()) {
        if (allowed.contains(key))
            continue;
        const QString near = names::nearest(key, allowed);
        return fail(join(path, key.toUtf8().constData()),
                    near.isEmpty()
                        ? MachineFile::tr("unknown key (known: %1)").arg(allowed.join(", "))
                        : MachineFile::tr("unknown key (did you mean %1?)").arg(near));
    }
    return true;
}

bool Reader::string(const QJsonObject& o, const QString& path, const char* key, QString* out,
                    bool required)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined()) {
        return !required || fail(join(path, key), MachineFile::tr("missing"));
    }
    if (!v.isString())
        return fail(join(path, key), MachineFile::tr("must be a text in quotes"));
    *out = v.toString();
    return true;
}

bool Reader::number(const QJsonObject& o, const QString& path, const char* key,
                    std::optional<double>* out)
{
    const QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined())
        return true;
    if (!v.isDouble() || !std::isfinite(v.toDouble()))
        return fail(join(path, key), MachineFile::tr("must be a decimal number"));
    *out = v.toDouble();
    return true;
}

bool Reader::readTop(const QJsonObject& top, MachineDescription* d)
{
    if (!onlyKeys(top, {},
                  {"format", "version", "name", "controllers", "axes", "spindle",
                   "crossControllerFeed", "limits", "subroutineFolder", "toolLength"}))
        return false;
    if (top.value("format").toString() != QLatin1String("stepdeck-machine"))
        return fail("format", MachineFile::tr("must be \"stepdeck-machine\""));
    const QJsonValue version = top.value("version");
    // Version 1 (before issue 32) mapped default axis names to addresses in an object; it is
    // read as it stands and written back as version 2.
    if (!version.isDouble() || (version.toDouble() != 1 && version.toDouble() != 2))
        return fail("version",
                    MachineFile::tr("must be 1 or 2 (the versions this StepDeck reads)"));
    m_version = int(version.toDouble());
    m_controllers = &d->controllers;
    if (!string(top, {}, "name", &d->name))
        return false;
    const QJsonValue controllers = top.value("controllers");
    if (!controllers.isArray())
        return fail("controllers", MachineFile::tr("must be a list of controllers"));
    for (qsizetype i = 0; i < controllers.toArray().size(); ++i) {
        MachineController c;
        if (!readController(controllers.toArray().at(i), QStringLiteral("controllers[%1]").arg(i),
                            &c))
            return false;
        d->controllers << c;
    }
    const QJsonValue axes = top.value("axes");
    if (!axes.isArray())
        return fail("axes", MachineFile::tr("must be a list of axes"));
    for (qsizetype i = 0; i < axes.toArray().size(); ++i) {
        MachineAxis a;
        if (!readAxis(axes.toArray().at(i), QStringLiteral("axes[%1]").arg(i), &a))
            return false;
        d->axes << a;
    }
    const QJsonValue cross = top.value("crossControllerFeed");
    if (!cross.isUndefined() && !cross.isBool())
        return fail("crossControllerFeed", MachineFile::tr("must be true or false"));
    d->crossControllerFeed = cross.toBool(true);
    if (!readLimits(top, d))
        return false;
    if (!string(top, {}, "subroutineFolder", &d->subroutineFolder, false) ||
        !readToolLength(top, d))
        return false;
    return !top.contains("spindle") || readSpindle(top.value("spindle"), &d->spindle);
}

// "limits" (issue 50): "clamp" (the default without the key) or "refuse"; any other word is
// refused, so that a typo never leaves a shop that wants refusals clamping.
bool Reader::readLimits(const QJsonObject& top, MachineDescription* d)
{
    const QJsonValue v = top.value("limits");
    if (v.isUndefined())
        return true;
    const std::optional<LimitPolicy> policy =
        v.isString() ? limitPolicyFromKey(v.toString()) : std::nullopt;
    if (!policy)
        return fail("limits", MachineFile::tr("must be \"clamp\" (run a feed or S above the "
                                              "machine's highest at that highest, the default) "
                                              "or \"refuse\" (refuse it in the check)"));
    d->limits = *policy;
    return true;
}

// "toolLength" (issue 50 item 4): "table" (the default without the key) or "touchOff"; any
// other word is refused, so that a typo never leaves a touch-off shop cutting with a table's
// lengths (or none).
bool Reader::readToolLength(const QJsonObject& top, MachineDescription* d)
{
    const QJsonValue v = top.value("toolLength");
    if (v.isUndefined())
        return true;
    const std::optional<ToolLength> mode =
        v.isString() ? toolLengthFromKey(v.toString()) : std::nullopt;
    if (!mode)
        return fail("toolLength",
                    MachineFile::tr("must be \"table\" (G43 takes the tool table's lengths, the "
                                    "default) or \"touchOff\" (Z is touched off after each tool "
                                    "change)"));
    d->toolLength = *mode;
    return true;
}

bool Reader::readSpindle(const QJsonValue& v, MachineSpindle* s)
{
    if (!v.isObject())
        return fail("spindle", MachineFile::tr("must be an object {\"maxRpm\": 24000}"));
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, "spindle", {"maxRpm", "laser"}) || !number(o, "spindle", "maxRpm", &s->maxRpm))
        return false;
    const QJsonValue laser = o.value("laser");
    if (!laser.isUndefined() && !laser.isBool())
        return fail("spindle.laser", MachineFile::tr("must be true (the spindle output drives a "
                                                     "laser) or false"));
    s->laser = laser.toBool(false);
    return true;
}

bool Reader::readController(const QJsonValue& v, const QString& path, MachineController* c)
{
    if (!v.isObject())
        return fail(path,
                    MachineFile::tr("must be an object {\"id\", \"model\", \"port\", \u2026}"));
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, path, {"id", "model", "port", "axes", "resetLine", "setup"}))
        return false;
    if (!string(o, path, "setup", &c->setupFile, false))
        return false;
    if (!string(o, path, "id", &c->id) || !string(o, path, "model", &c->modelId) ||
        !string(o, path, "port", &c->port))
        return false;
    if (o.contains("axes") && !readAddresses(o.value("axes"), join(path, "axes"), c))
        return false;
    QString line;
    if (!string(o, path, "resetLine", &line, false))
        return false;
    if (o.contains("resetLine")) {
        c->resetLine = resetLineFromName(line);
        if (!c->resetLine)
            return fail(join(path, "resetLine"), MachineFile::tr("must be \"rts\" or \"dtr\""));
    }
    return true;
}

bool Reader::readAddressesV1(const QJsonValue& v, const QString& path, MachineController* c)
{
    if (!v.isObject() || v.toObject().isEmpty())
        return fail(path, MachineFile::tr("must map controller axes to bus addresses, e.g. "
                                          "{\"X\": 1, \"Y\": 2}"));
    const QJsonObject o = v.toObject();
    for (auto it = o.begin(); it != o.end(); ++it) {
        const QString field = path + QLatin1Char('.') + it.key();
        const std::optional<Axis> axis = axisFromName(it.key());
        if (!axis || axisName(*axis) != it.key())
            return fail(field, MachineFile::tr("not a controller axis (X, Y, Z or U)"));
        if (!it.value().isDouble() || !isWhole(it.value().toDouble()))
            return fail(field, MachineFile::tr("must be a whole bus address"));
        c->busAddresses.insert(*axis, int(it.value().toDouble()));
    }
    return true;
}

// Version 2: an ordered list [{"name": "feeder", "address": 5}, ...] (assignBusAxes).
bool Reader::readAddresses(const QJsonValue& v, const QString& path, MachineController* c)
{
    if (m_version == 1)
        return readAddressesV1(v, path, c);
    if (!v.isArray() || v.toArray().isEmpty())
        return fail(path, MachineFile::tr("must list the controller's axes, e.g. "
                                          "[{\"name\": \"X\", \"address\": 1}]"));
    QList<NamedAddress> list;
    const QJsonArray entries = v.toArray();
    for (qsizetype i = 0; i < entries.size(); ++i) {
        const QString field = path + QStringLiteral("[%1]").arg(i);
        const QJsonObject e = entries.at(i).toObject();
        if (!entries.at(i).isObject())
            return fail(field, MachineFile::tr("must be an object {\"name\", \"address\"}"));
        NamedAddress entry;
        std::optional<double> address;
        if (!onlyKeys(e, field, {"name", "address"}) || !string(e, field, "name", &entry.name) ||
            !number(e, field, "address", &address))
            return false;
        if (!AxisNames::isValidName(entry.name))
            return fail(join(field, "name"),
                        MachineFile::tr("must be X, Y, Z, U or a letter and then letters, digits "
                                        "or _ (2 to 32 characters)"));
        if (!address || !isWhole(*address))
            return fail(join(field, "address"), MachineFile::tr("must be a whole bus address"));
        entry.address = int(*address);
        list << entry;
    }
    QString why;
    if (!assignBusAxes(list, &c->busAddresses, &c->axisNames, &why))
        return fail(path, why);
    return true;
}

bool Reader::readAxis(const QJsonValue& v, const QString& path, MachineAxis* a)
{
    if (!v.isObject())
        return fail(path, MachineFile::tr("must be an object {\"name\", \"controller\", \"axis\", "
                                          "\"unit\", \u2026}"));
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, path,
                  {"name", "controller", "axis", "unit", "stepsPerUnit", "invert", "softLimits",
                   "maxJogSpeed", "jogAcceleration", "reference"}))
        return false;
    return readAxisValues(o, path, a);
}

bool Reader::readAxisValues(const QJsonObject& o, const QString& path, MachineAxis* a)
{
    QString controllerAxis, unit;
    if (!string(o, path, "name", &a->name) || !string(o, path, "controller", &a->controller) ||
        !string(o, path, "axis", &controllerAxis) || !string(o, path, "unit", &unit))
        return false;
    // The controller's own names first ("feeder"), read before the axes; an unknown
    // controller is reported by the validation.
    AxisNames names;
    for (const MachineController& c : *m_controllers) {
        if (c.id == a->controller)
            names = c.axisNames;
    }
    const std::optional<Axis> axis = names.find(controllerAxis);
    if (!axis || names.name(*axis) != controllerAxis)
        return fail(join(path, "axis"),
                    MachineFile::tr("not an axis of its controller (X, Y, Z, U, axis5 \u2026 or "
                                    "a name the controller gives)"));
    a->axis = *axis;
    const std::optional<AxisUnit> parsedUnit = unitFromKey(unit);
    if (!parsedUnit)
        return fail(join(path, "unit"), MachineFile::tr("must be \"mm\", \"deg\" or \"steps\""));
    a->unit = *parsedUnit;
    std::optional<double> steps;
    if (!number(o, path, "stepsPerUnit", &steps))
        return false;
    if (!steps && a->unit != AxisUnit::Step)
        return fail(join(path, "stepsPerUnit"), MachineFile::tr("missing"));
    a->stepsPerUnit = steps.value_or(1.0);
    const QJsonValue invert = o.value("invert");
    if (!invert.isUndefined() && !invert.isBool())
        return fail(join(path, "invert"), MachineFile::tr("must be true or false"));
    a->invert = invert.toBool(false);
    if (o.contains("softLimits") && !readSoftLimits(o.value("softLimits"), path, a))
        return false;
    if (!number(o, path, "maxJogSpeed", &a->maxJogSpeed) ||
        !number(o, path, "jogAcceleration", &a->jogAcceleration))
        return false;
    return !o.contains("reference") || readReference(o.value("reference"), path, a);
}

bool Reader::readSoftLimits(const QJsonValue& v, const QString& path, MachineAxis* a)
{
    const QJsonArray pair = v.toArray();
    if (!v.isArray() || pair.size() != 2 || !pair.at(0).isDouble() || !pair.at(1).isDouble())
        return fail(join(path, "softLimits"),
                    MachineFile::tr("must be [minimum, maximum] in the axis' unit"));
    a->softMinimum = pair.at(0).toDouble();
    a->softMaximum = pair.at(1).toDouble();
    return true;
}

bool Reader::readReference(const QJsonValue& v, const QString& path, MachineAxis* a)
{
    const QString field = join(path, "reference");
    if (!v.isObject())
        return fail(field, MachineFile::tr("must be an object {\"direction\", \"order\"}"));
    const QJsonObject o = v.toObject();
    if (!onlyKeys(o, field, {"direction", "order"}))
        return false;
    const QJsonValue direction = o.value("direction");
    if (!direction.isUndefined()) {
        if (!direction.isDouble() || std::fabs(direction.toDouble()) != 1)
            return fail(join(field, "direction"), MachineFile::tr("must be -1 or 1"));
        a->referenceDirection = int(direction.toDouble());
    }
    const QJsonValue order = o.value("order");
    if (!order.isUndefined()) {
        if (!order.isDouble() || !isWhole(order.toDouble()))
            return fail(join(field, "order"), MachineFile::tr("must be a whole number"));
        a->referenceOrder = int(order.toDouble());
    }
    return true;
}

// Line and column (1-based) of a byte offset, as an editor counts them.
void locate(const QByteArray& text, int offset, int* line, int* column)
{
    *line = 1;
    int lineStart = 0;
    for (int i = 0; i < offset && i < text.size(); ++i) {
        if (text.at(i) == '\n') {
            ++*line;
            lineStart = i + 1;
        }
    }
    *column = QString::fromUtf8(text.mid(lineStart, offset - lineStart)).size() + 1;
}

} // namespace

bool MachineFileError::report(MachineFileError* error, const QString& field, const QString& message)
{
    if (error) {
        *error = {};
        error->field = field;
        error->message = message;
    }
    return false;
}

QString MachineFileError::text() const
{
    if (line > 0)
        return MachineFile::tr("line %1, column %2: %3").arg(line).arg(column).arg(message);
    return field.isEmpty() ? message : field + QStringLiteral(": ") + message;
}

std::optional<MachineDescription>
MachineFile::parse(const QByteArray& json, MachineFileError* error, const QString& baseDir)
{
    MachineFileError local;
    MachineFileError* e = error ? error : &local;
    std::optional<MachineDescription> d = readStructure(json, e);
    if (!d || !validate(*d, e) || !loadSetups(&*d, baseDir, e))
        return std::nullopt;
    if (!d->subroutineFolder.isEmpty())
        d->subroutineFolderPath =
            QDir::cleanPath(QDir(baseDir.isEmpty() ? QDir::currentPath() : baseDir)
                                .absoluteFilePath(d->subroutineFolder));
    return d;
}

void MachineFile::anchorSetupFiles(MachineDescription* machine, const QString& machinePath)
{
    const QDir base = QFileInfo(machinePath).absoluteDir();
    for (MachineController& c : machine->controllers)
        if (!c.setupFile.isEmpty())
            c.setupFile = QDir::cleanPath(base.absoluteFilePath(c.setupFile));
}

bool MachineFile::loadSetups(MachineDescription* d, const QString& baseDir, MachineFileError* e)
{
    const QDir base(baseDir.isEmpty() ? QDir::currentPath() : baseDir);
    for (qsizetype i = 0; i < d->controllers.size(); ++i) {
        MachineController& c = d->controllers[i];
        if (c.setupFile.isEmpty())
            continue;
        const QString field = QStringLiteral("controllers[%1].setup").arg(i);
        const ModelInfo* model = findModel(c.modelId); // validate() found it
        if (!model)
            return MachineFileError::report(e, field, tr("unknown model"));
        const QList<Axis> axes =
            c.busAddresses.isEmpty() ? model->capabilities.axes : c.busAddresses.keys();
        QString why;
        ParameterSet set;
        if (ParameterFile::load(model->schema, model->id, axes, base.filePath(c.setupFile), &set,
                                &why) != ParameterFile::Status::Ok)
            return MachineFileError::report(e, field, why);
        if (set.isEmpty())
            return MachineFileError::report(e, field, tr("%1 holds no parameter").arg(c.setupFile));
        c.setup = set;
    }
    return true;
}

std::optional<MachineDescription> MachineFile::parseDraft(const QByteArray& json,
                                                          MachineFileError* error)
{
    MachineFileError local;
    MachineFileError* e = error ? error : &local;
    std::optional<MachineDescription> d = readStructure(json, e);
    if (d)
        validate(*d, e); // the first rule it breaks, for the editor to mark
    return d;
}

std::optional<MachineDescription> MachineFile::readStructure(const QByteArray& json,
                                                             MachineFileError* e)
{
    *e = {};
    if (json.trimmed().isEmpty()) {
        e->message = tr("the file is empty: a machine file holds a JSON object with \"format\": "
                        "\"stepdeck-machine\"");
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        locate(json, parseError.offset, &e->line, &e->column);
        e->message = parseError.errorString();
        return std::nullopt;
    }
    if (!doc.isObject()) {
        e->message = tr("not a machine file: it holds no JSON object");
        return std::nullopt;
    }
    MachineDescription d;
    if (!Reader(e).readTop(doc.object(), &d))
        return std::nullopt;
    return d;
}

std::optional<QByteArray> MachineFile::read(const QString& path, MachineFileError* error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) {
            *error = {};
            error->message = tr("cannot open %1: %2").arg(path, file.errorString());
        }
        return std::nullopt;
    }
    return file.readAll();
}

std::optional<MachineDescription> MachineFile::load(const QString& path, MachineFileError* error)
{
    const std::optional<QByteArray> text = read(path, error);
    return text ? parse(*text, error, QFileInfo(path).absolutePath()) : std::nullopt;
}

std::optional<MachineDescription> MachineFile::loadDraft(const QString& path,
                                                         MachineFileError* error)
{
    const std::optional<QByteArray> text = read(path, error);
    return text ? parseDraft(*text, error) : std::nullopt;
}

bool MachineFile::save(const MachineDescription& machine, const QString& path, QString* error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(QJsonDocument(machine.toJson()).toJson(QJsonDocument::Indented)) < 0 ||
        !file.commit()) {
        if (error)
            *error = tr("cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace stepdeck::machine
