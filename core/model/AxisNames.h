#pragma once
#include "model/Axis.h"
#include <QCoreApplication>

namespace stepdeck {

// The names one controller gives its axes (issue 32, step 3): a bus of Nanotec drives names
// them "feeder", "gate", ... An axis without a name of its own goes by its default name
// (axisName: X, Y, Z, U, axis5, ...). Default names are reserved for their own axes, so a name
// always means one axis: "X" is never another axis' name.
class AxisNames
{
    Q_DECLARE_TR_FUNCTIONS(stepdeck::AxisNames)
public:
    static constexpr int kMaxNameLength = 32;

    // X, Y, Z, U, or a letter, then letters, digits or '_', 2..kMaxNameLength characters (a
    // single other letter would read as a machine axis: "A=1").
    static bool isValidName(QStringView name);
    static QString invalidNameText(const QString& name);

    QString name(Axis axis) const;
    // An own name, or a default name (which always means its axis, named or not: model
    // operations and saved settings use them); case-insensitive.
    std::optional<Axis> find(QStringView name) const;
    // False with the reason: not a valid name, a default name of another axis, or another
    // axis' name already. A default name of the axis itself clears its own name.
    bool setName(Axis axis, const QString& name, QString* error);
    const QMap<Axis, QString>& ownNames() const { return m_names; }
    bool isEmpty() const { return m_names.isEmpty(); }

    friend bool operator==(const AxisNames& a, const AxisNames& b)
    {
        return a.m_names == b.m_names;
    }
    friend bool operator!=(const AxisNames& a, const AxisNames& b) { return !(a == b); }

private:
    QMap<Axis, QString> m_names;
};

// One entry of an ordered list of bus axes: "feeder=5" (CLI --axes, machine files).
struct NamedAddress
{
    QString name;
    int address = 0;
};

// The axes of a bus from its ordered list (issue 32, step 3). An entry with a default name
// (X, Y, Z, U, axis5, ...) is that axis, as in the files and command lines before names
// existed ("Y=2" alone is axis Y); every other entry takes the lowest axis no entry claims, in
// list order, so "feeder=5,gate=6" is feeder the first axis and gate the second. Names are
// unique (case-insensitive); addresses are not checked here (the model does, 1.1).
bool assignBusAxes(const QList<NamedAddress>& list, QMap<Axis, int>* addresses, AxisNames* names,
                   QString* error);
// "feeder=5,gate=6" -> entries; false with the reason for a malformed entry.
bool parseNamedAddresses(const QString& text, QList<NamedAddress>* out, QString* error);
// The list back in axis order, every axis by its name: "feeder=5,gate=6".
QList<NamedAddress> namedAddresses(const QMap<Axis, int>& addresses, const AxisNames& names);

} // namespace stepdeck
