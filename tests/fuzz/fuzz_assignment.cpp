// libFuzzer target: "NAME=V[,V,V]" as typed on the CLI (ParameterSchema::parseAssignment)
// and the decimal number parser behind it and behind every other number a person types
// (model/NumberParsing.h). Invariants: an accepted assignment holds canonical in-range
// values and survives formatValue -> parseAssignment; a refused one says why; integers are
// decimal only and agree with a plain reference reading; reals are finite; nan/inf are
// always NonFinite.
#include "FuzzSupport.h"
#include "SchemaSupport.h"
#include "model/NumberParsing.h"
#include <QRegularExpression>

using namespace stepdeck;

namespace {
void checkAssignment(const fuzz::ModelSchema& m, const QString& text)
{
    QString name;
    QString error;
    ParameterValue value;
    NumberError why = NumberError::None;
    if (!m.schema.parseAssignment(text, m.axes, &name, &value, &error, &why)) {
        FUZZ_CHECK(!error.isEmpty(), text);
        return;
    }
    const ParameterSpec* spec = m.schema.find(name);
    FUZZ_CHECK(spec && error.isEmpty() && why == NumberError::None, text);
    FUZZ_CHECK(value.isPerAxis() == spec->perAxis, text);
    if (spec->perAxis) {
        FUZZ_CHECK(value.perAxis.size() == m.axes.size(), text);
        for (const QVariant& v : value.perAxis)
            FUZZ_CHECK(fuzz::canonical(*spec, v), text);
    } else {
        FUZZ_CHECK(fuzz::canonical(*spec, value.global), text);
    }
    const QString again = name + QLatin1Char('=') + m.schema.formatValue(*spec, value);
    ParameterValue reparsed;
    FUZZ_CHECK(m.schema.parseAssignment(again, m.axes, &name, &reparsed, &error), again + error);
    FUZZ_CHECK(reparsed == value, text + " -> " + again);
}

void checkNumbers(const QString& text)
{
    static const QRegularExpression decimal(QStringLiteral("^[+-]?[0-9]+$"));
    static const QRegularExpression nonFinite(QStringLiteral("^[+-]?(nan|inf|infinity)$"),
                                              QRegularExpression::CaseInsensitiveOption);
    const QString trimmed = text.trimmed(); // the parser ignores the same blanks around it
    qint64 integer = 0;
    const NumberError e = numbers::parseInteger(text, &integer);
    if (nonFinite.match(trimmed).hasMatch()) {
        FUZZ_CHECK(e == NumberError::NonFinite, text);
    } else if (decimal.match(trimmed).hasMatch()) {
        // Reference: Qt's base-10 reading of the same digits.
        bool ok = false;
        const qint64 reference = trimmed.toLongLong(&ok, 10);
        FUZZ_CHECK(ok ? e == NumberError::None && integer == reference
                      : e == NumberError::OutOfRange,
                   text);
    } else {
        FUZZ_CHECK(e == NumberError::Malformed, text);
    }
    double real = 0;
    const NumberError r = numbers::parseReal(text, &real);
    if (r == NumberError::None)
        FUZZ_CHECK(qIsFinite(real), text);
    if (e == NumberError::None && qAbs(integer) < (qint64(1) << 53))
        FUZZ_CHECK(r == NumberError::None && real == double(integer), text);
    if (e == NumberError::NonFinite)
        FUZZ_CHECK(r == NumberError::NonFinite, text);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QString text = QString::fromUtf8(fuzz::input(data, size));
    checkNumbers(text);
    for (const fuzz::ModelSchema& m : fuzz::schemas())
        checkAssignment(m, text);
    return 0;
}
