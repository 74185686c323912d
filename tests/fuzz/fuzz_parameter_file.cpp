// libFuzzer target: parameter files (ParameterSchema::fromJson, shared by the CLI's import
// and the setup pages), against the real E-LAB and Nanotec schemas. Input that is JSON but
// no parameter file is also tried as the "parameters" object of one, so the fuzzer reaches
// the values quickly. Invariants: no crash or undefined behaviour on any input (1e300 was a
// float-cast overflow); a refused file says why and leaves the output alone; an accepted set
// validates, holds only canonical in-range values, and survives toJson -> text -> fromJson.
#include "FuzzSupport.h"
#include "SchemaSupport.h"
#include <QJsonDocument>
#include <QJsonObject>

using namespace stepdeck;

namespace {
void check(const fuzz::ModelSchema& m, const QJsonObject& file)
{
    ParameterSet set;
    set.insert(QStringLiteral("sentinel"), ParameterValue{});
    QString error;
    if (!m.schema.fromJson(file, m.id, m.axes, &set, &error)) {
        FUZZ_CHECK(!error.isEmpty(), "refused without a reason");
        FUZZ_CHECK(set.size() == 1 && set.contains(QStringLiteral("sentinel")), error);
        return;
    }
    FUZZ_CHECK(error.isEmpty(), error);
    FUZZ_CHECK(m.schema.validate(set, m.axes).isEmpty(), m.schema.validate(set, m.axes));
    for (auto it = set.cbegin(); it != set.cend(); ++it) {
        const ParameterSpec* spec = m.schema.find(it.key());
        FUZZ_CHECK(spec && spec->writable, it.key());
        if (it.value().isPerAxis()) {
            for (const QVariant& v : it.value().perAxis)
                FUZZ_CHECK(fuzz::canonical(*spec, v), it.key() + "=" + v.toString());
        } else {
            FUZZ_CHECK(fuzz::canonical(*spec, it.value().global),
                       it.key() + "=" + it.value().global.toString());
        }
    }
    const QByteArray text = QJsonDocument(m.schema.toJson(m.id, set)).toJson();
    ParameterSet again;
    FUZZ_CHECK(
        m.schema.fromJson(QJsonDocument::fromJson(text).object(), m.id, m.axes, &again, &error),
        error);
    FUZZ_CHECK(again == set, QString::fromUtf8(text));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    const QJsonDocument doc = QJsonDocument::fromJson(fuzz::input(data, size));
    if (!doc.isObject())
        return 0;
    const QJsonObject object = doc.object();
    for (const fuzz::ModelSchema& m : fuzz::schemas()) {
        check(m, object);
        if (!object.contains(QStringLiteral("format"))) {
            check(m, QJsonObject{{"format", "stepdeck-parameters"},
                                 {"version", 1},
                                 {"model", m.id},
                                 {"parameters", object}});
        }
    }
    return 0;
}
