#pragma once
#include <QString>
#include <QVariant>

namespace stepdeck {

// Why a text or a value is not the number that was asked for.
enum class NumberError {
    None,
    Malformed,  // not decimal notation: empty, letters, "0x40", "1 000", "12.5" for an integer
    NonFinite,  // "nan", "inf", "infinity" (any case, either sign): never a usable value
    OutOfRange, // decimal, but outside the range asked for or representable
};

// The one place where input typed by people or read from their files becomes a number: the
// CLI's arguments, parameter files, the setup pages' fields, the simulator's options. Device
// replies are decoded by the protocol codecs, not here.
//
// The notation is decimal, always:
// - integers: optional '+' or '-', then ASCII digits only. A leading zero is just a zero
//   ("0100" is one hundred, never octal); "0x40", "1e3", "12.5", "1_000" and non-ASCII
//   digits are Malformed. Whitespace around the number is ignored, inside it is not.
// - reals: optional sign, digits with an optional '.' fraction and an optional decimal
//   exponent ("1500", "-2.5", ".5", "1e3"); no hexadecimal floats, no locale separators.
//   A result that does not fit a double ("1e400") is OutOfRange.
// - "nan", "inf", "infinity" are NonFinite wherever a number is expected, so callers can
//   refuse them as usage errors.
namespace numbers {

NumberError parseInteger(QStringView text, qint64* value);
// As above, and OutOfRange unless minimum <= value <= maximum.
NumberError parseInteger(QStringView text, qint64 minimum, qint64 maximum, qint64* value);
NumberError parseInt(QStringView text, int minimum, int maximum, int* value);
NumberError parseReal(QStringView text, double* value);

// A double that must be a whole number (a JSON number): non-finite values are NonFinite,
// fractions Malformed, anything outside qint64 OutOfRange -- checked as double before the
// conversion, which would otherwise be undefined behaviour.
NumberError integerFromDouble(double value, qint64* out);
// Any QVariant that should hold an integer: text is parsed as above, doubles as above,
// integral types are taken as they are (unsigned ones beyond qint64 are OutOfRange); booleans
// and everything else are Malformed.
NumberError integerFromVariant(const QVariant& value, qint64* out);

// True for "nan", "inf", "infinity" with an optional sign, in any case.
bool isNonFiniteWord(QStringView text);

} // namespace numbers
} // namespace stepdeck
