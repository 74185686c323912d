// AXIS=VALUE arguments ("X=100 Y=-5", "X=1.5e3") and the --axes map ("X=1,Y=2"): decimal
// numbers only (core/model/NumberParsing), a usage error for anything else.
#include "CliArguments.h"
#include "model/NumberParsing.h"
#include <QCoreApplication>
#include <limits>

namespace stepdeck::cli {

namespace {
struct CliAxisArguments
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::cli::CliAxisArguments)
};

// Parse: (QStringView text, T* value) -> NumberError. A failure is an Outcome whose message
// does not name the command yet.
template <typename T, typename Parse>
Outcome parseAxisAssignments(const QStringList& args, const QList<Axis>& axes,
                             const AxisNames& axisNames, QMap<Axis, T>* out, Parse parse)
{
    QStringList names;
    for (Axis a : axes)
        names << axisNames.name(a);
    const auto noSuchAxis = [&names](const QString& name) {
        return Outcome::usage(CliAxisArguments::tr("this machine has no axis %1 (its axes: %2)")
                                  .arg(name, names.join(QStringLiteral(", "))));
    };
    QMap<Axis, T> result;
    for (const QString& arg : args) {
        const int eq = arg.indexOf(QLatin1Char('='));
        const QString name = eq > 0 ? arg.left(eq).trimmed() : QString();
        const auto axis = axisNames.find(name); // "feeder", or a default name (issue 32)
        // One letter before '=' is meant as an axis ("Q=5"): say there is no such axis.
        if (!axis && name.size() == 1 && name.at(0).isLetter())
            return noSuchAxis(name.toUpper());
        if (!axis)
            return Outcome::usage(
                CliAxisArguments::tr("expected AXIS=VALUE (e.g. X=100), got '%1'").arg(arg));
        if (!axes.contains(*axis))
            return noSuchAxis(axisNames.name(*axis));
        if (result.contains(*axis))
            return Outcome::usage(
                CliAxisArguments::tr("axis %1 given twice").arg(axisNames.name(*axis)));
        T value{};
        const QString text = arg.mid(eq + 1);
        switch (parse(QStringView(text), &value)) {
        case NumberError::None:
            break;
        case NumberError::Malformed:
            return Outcome::usage(CliAxisArguments::tr("%1: '%2' is not a decimal number")
                                      .arg(axisNames.name(*axis), text));
        case NumberError::NonFinite:
            return Outcome::usage(CliAxisArguments::tr("%1: '%2' is not a finite number")
                                      .arg(axisNames.name(*axis), text));
        case NumberError::OutOfRange:
            return Outcome::failure(
                ExitInvalidValue,
                CliAxisArguments::tr("%1: '%2' is out of range").arg(axisNames.name(*axis), text));
        }
        result.insert(*axis, value);
    }
    if (result.isEmpty())
        return Outcome::usage(CliAxisArguments::tr("no axis given (e.g. X=100 Y=0 Z=-50)"));
    *out = result;
    return Outcome::success();
}

Outcome named(const QString& command, Outcome outcome)
{
    if (!outcome.ok())
        outcome.message = CliAxisArguments::tr("%1: %2").arg(command, outcome.message);
    return outcome;
}

} // namespace

Outcome parseAxisIntegers(const QString& command, const QStringList& args, const QList<Axis>& axes,
                          AxisVector* out, const AxisNames& names)
{
    return named(command,
                 parseAxisAssignments<qint64>(args, axes, names, out, [](QStringView s, qint64* v) {
                     return numbers::parseInteger(s, v);
                 }));
}

Outcome parseAxisDoubles(const QString& command, const QStringList& args, const QList<Axis>& axes,
                         AxisVelocities* out, const AxisNames& names)
{
    return named(command,
                 parseAxisAssignments<double>(args, axes, names, out, [](QStringView s, double* v) {
                     return numbers::parseReal(s, v);
                 }));
}

bool parseAxisMap(const QString& text, QMap<Axis, int>* addresses, AxisNames* names, QString* error)
{
    QList<NamedAddress> list;
    QString why;
    if (!parseNamedAddresses(text, &list, &why) || !assignBusAxes(list, addresses, names, &why)) {
        *error = CliAxisArguments::tr("--axes: %1").arg(why);
        return false;
    }
    return true;
}

} // namespace stepdeck::cli
