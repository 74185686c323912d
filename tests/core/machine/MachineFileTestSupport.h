#pragma once
// Shared by the machine file tests: the first example of docs/machines.md as a version 1 file
// (the migration's input too) and edits of it that break one field at a time.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

namespace stepdeck::test {

// E-LAB XYZ table + Nanotec rotary A: the first example of docs/machines.md.
inline QJsonObject tableAndRotary()
{
    const QByteArray json = R"({
  "format": "stepdeck-machine", "version": 1, "name": "Engraver",
  "controllers": [
    {"id": "table", "model": "elab", "port": "/dev/ttyUSB0", "resetLine": "dtr"},
    {"id": "rotary", "model": "nanotec", "port": "/dev/ttyUSB1", "axes": {"X": 1}}
  ],
  "axes": [
    {"name": "X", "controller": "table", "axis": "X", "unit": "mm", "stepsPerUnit": 400,
     "softLimits": [0, 300], "maxJogSpeed": 2, "jogAcceleration": 8,
     "reference": {"direction": -1, "order": 1}},
    {"name": "Y", "controller": "table", "axis": "Y", "unit": "mm", "stepsPerUnit": 400,
     "invert": true, "reference": {"order": 1}},
    {"name": "Z", "controller": "table", "axis": "Z", "unit": "mm", "stepsPerUnit": 800,
     "reference": {"direction": 1, "order": 0}},
    {"name": "A", "controller": "rotary", "axis": "X", "unit": "deg", "stepsPerUnit": 88.8889}
  ]
})";
    return QJsonDocument::fromJson(json).object();
}

inline QByteArray bytes(const QJsonObject& o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

// Sets a value at a path such as "axes.2.stepsPerUnit" ("-" removes the key).
inline QJsonValue edited(const QJsonValue& at, QStringList path, const QJsonValue& value,
                         bool remove)
{
    const QString key = path.takeFirst();
    if (at.isArray()) {
        QJsonArray array = at.toArray();
        const int index = key.toInt();
        array[index] = path.isEmpty() ? value : edited(array.at(index), path, value, remove);
        return array;
    }
    QJsonObject object = at.toObject();
    if (path.isEmpty()) {
        if (remove)
            object.remove(key);
        else
            object.insert(key, value);
    } else {
        object.insert(key, edited(object.value(key), path, value, remove));
    }
    return object;
}

inline QByteArray withEdit(const QString& path, const QJsonValue& value, bool remove = false)
{
    return bytes(edited(tableAndRotary(), path.split('.'), value, remove).toObject());
}

inline bool writeFile(const QString& path, const QByteArray& content)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(content) == content.size();
}

} // namespace stepdeck::test
