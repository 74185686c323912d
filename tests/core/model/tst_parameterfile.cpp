// ParameterFile: the one reader and writer of parameter files (GUI setup pages and CLI
// export/import), with the E-LAB schema as the real-world example.
#include "TestMain.h"
#include "model/ParameterFile.h"
#include "protocols/elab/ElabModel.h"
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>
#include <cerrno>
#include <csignal>
#include <sys/resource.h>
#include <unistd.h>

using namespace stepdeck;
using Status = ParameterFile::Status;

Q_DECLARE_METATYPE(stepdeck::ParameterFile::Status)

namespace {
const QList<Axis> kFileXyz{Axis::X, Axis::Y, Axis::Z};

ParameterSet sampleSet()
{
    ParameterSet set;
    set[QStringLiteral("start-speed")].perAxis = {
        {Axis::X, qint64(100)}, {Axis::Y, qint64(200)}, {Axis::Z, qint64(300)}};
    set[QStringLiteral("drive-power")].global = qint64(66);
    set[QStringLiteral("coolant")].global = true;
    return set;
}

const QByteArray kHead = R"({"format":"stepdeck-parameters","version":1,"model":"elab",
    "parameters":{"start-speed":{"X":100,"Y":100,"Z":100})";
} // namespace

class TestParameterFile : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void roundTrip_keepsEveryValueAndExtraKeys();
    void load_missingFile_isFileError();
    void load_broken_namesTheCause_data();
    void load_broken_namesTheCause();
    void load_error_leavesTheSetUntouched();
    void save_folderMissing_isFileErrorAndSaysWhy();
    void save_unwritableFolder_isFileError();
    void save_failedWrite_keepsTheOldFile();
    void save_overwrites_noTemporaryFilesLeft();

private:
    Status write(const QString& name, const QByteArray& content, ParameterSet* set, QString* error);
    ParameterSchema m_schema = elab::parameterSchema();
    std::unique_ptr<QTemporaryDir> m_dir;
};

void TestParameterFile::init()
{
    m_dir = std::make_unique<QTemporaryDir>();
    QVERIFY(m_dir->isValid());
}

Status TestParameterFile::write(const QString& name, const QByteArray& content, ParameterSet* set,
                                QString* error)
{
    const QString path = m_dir->filePath(name);
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(content) != content.size())
        return Status::FileError;
    file.close();
    return ParameterFile::load(m_schema, QStringLiteral("elab"), kFileXyz, path, set, error);
}

void TestParameterFile::roundTrip_keepsEveryValueAndExtraKeys()
{
    const QString path = m_dir->filePath(QStringLiteral("machine.json"));
    QString error;
    const QJsonObject origin{{QStringLiteral("drive-power"), QStringLiteral("default")}};
    QCOMPARE(ParameterFile::save(m_schema, QStringLiteral("elab"), sampleSet(), path, &error,
                                 {{QStringLiteral("origin"), origin}}),
             Status::Ok);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(json.value(QStringLiteral("format")).toString(),
             QStringLiteral("stepdeck-parameters"));
    QCOMPARE(json.value(QStringLiteral("origin")).toObject(), origin);
    ParameterSet loaded;
    QCOMPARE(ParameterFile::load(m_schema, QStringLiteral("elab"), kFileXyz, path, &loaded, &error),
             Status::Ok);
    QCOMPARE(loaded, sampleSet());
}

void TestParameterFile::load_missingFile_isFileError()
{
    const QString path = m_dir->filePath(QStringLiteral("nothing-here.json"));
    ParameterSet set;
    QString error;
    QCOMPARE(ParameterFile::load(m_schema, QStringLiteral("elab"), kFileXyz, path, &set, &error),
             Status::FileError);
    QVERIFY2(error.startsWith(QStringLiteral("Cannot open ") + path + QStringLiteral(": ")),
             qPrintable(error));
    QVERIFY2(error.size() > path.size() + 14, qPrintable(error)); // the system's reason
}

void TestParameterFile::load_broken_namesTheCause_data()
{
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<Status>("status");
    QTest::addColumn<QString>("needle");
    // A missing comma at the end of line 2: the parser stops inside the next key, line 3.
    QTest::newRow("syntax") << QByteArray("{\n  \"format\": \"stepdeck-parameters\"\n  \"v\": 1\n}")
                            << Status::NotJson << "f.json, line 3, column 4: ";
    QTest::newRow("column counts characters")
        << QByteArray("{\"\xc3\xa4\xc3\xb6\": 1,,}") << Status::NotJson << "line 1, column 11";
    QTest::newRow("empty") << QByteArray() << Status::NotJson
                           << "f.json is empty: a StepDeck parameter file holds a JSON object";
    QTest::newRow("only blank lines")
        << QByteArray(" \n\t\r\n") << Status::NotJson << "f.json is empty";
    QTest::newRow("array") << QByteArray("[1, 2]") << Status::NotJson
                           << "is not a parameter file: it holds no JSON object";
    QTest::newRow("other format") << QByteArray(R"({"format":"x"})") << Status::Invalid
                                  << "f.json: not a StepDeck parameter file";
    QTest::newRow("unknown name") << kHead + R"(,"warp-speed":9}})" << Status::Invalid
                                  << "f.json: unknown parameter 'warp-speed'";
    QTest::newRow("out of range") << kHead + R"(,"drive-power":101}})" << Status::Invalid
                                  << "drive-power: value '101' is out of range";
    // The same words as the setup page's field for the same text (issue 16).
    QTest::newRow("not a number") << kHead + R"(,"drive-power":"abc"}})" << Status::Invalid
                                  << "drive-power: 'abc' is not a decimal integer (allowed: "
                                     "0..100 %)";
    QTest::newRow("huge number") << kHead + R"(,"drive-power":1e300}})" << Status::Invalid
                                 << "drive-power";
    QTest::newRow("not an axis") << kHead + R"(,"feed-speed":{"X":5,"W":5}}})" << Status::Invalid
                                 << "'W' is not an axis";
    QTest::newRow("other model") << QByteArray(kHead).replace("\"elab\"", "\"nanotec\"") + "}}"
                                 << Status::Invalid << "nanotec";
}

void TestParameterFile::load_broken_namesTheCause()
{
    QFETCH(QByteArray, content);
    QFETCH(Status, status);
    QFETCH(QString, needle);
    ParameterSet set;
    QString error;
    QCOMPARE(write(QStringLiteral("f.json"), content, &set, &error), status);
    QVERIFY2(error.contains(needle), qPrintable(error));
    QVERIFY(set.isEmpty());
}

void TestParameterFile::load_error_leavesTheSetUntouched()
{
    ParameterSet set = sampleSet();
    QString error;
    QCOMPARE(write(QStringLiteral("f.json"), kHead + R"(,"drive-power":-1}})", &set, &error),
             Status::Invalid);
    QCOMPARE(set, sampleSet());
}

void TestParameterFile::save_folderMissing_isFileErrorAndSaysWhy()
{
    // The parent is a regular file: no folder can be created there, not even by root.
    QFile blocker(m_dir->filePath(QStringLiteral("not-a-folder")));
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    const QString path = blocker.fileName() + QStringLiteral("/machine.json");
    QString error;
    QCOMPARE(ParameterFile::save(m_schema, QStringLiteral("elab"), sampleSet(), path, &error),
             Status::FileError);
    QVERIFY2(error.startsWith(QStringLiteral("Cannot write ") + path + QStringLiteral(": ")),
             qPrintable(error));
    QVERIFY2(error.size() > path.size() + 15, qPrintable(error));
}

void TestParameterFile::save_unwritableFolder_isFileError()
{
    if (geteuid() == 0)
        QSKIP("root writes into read-only folders; save_failedWrite_keepsTheOldFile covers it");
    QVERIFY(QFile::setPermissions(m_dir->path(), QFileDevice::ReadOwner | QFileDevice::ExeOwner));
    QString error;
    const Status status = ParameterFile::save(m_schema, QStringLiteral("elab"), sampleSet(),
                                              m_dir->filePath(QStringLiteral("m.json")), &error);
    QFile::setPermissions(m_dir->path(),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    QCOMPARE(status, Status::FileError);
    QVERIFY2(error.startsWith(QStringLiteral("Cannot write ")), qPrintable(error));
}

void TestParameterFile::save_failedWrite_keepsTheOldFile()
{
    const QString path = m_dir->filePath(QStringLiteral("machine.json"));
    const QByteArray old = "the old file, to be kept";
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(old);
    file.close();
    // A file size limit smaller than the new content makes the write itself fail (EFBIG),
    // for root too, half-way through: the case a plain truncate-and-write would corrupt.
    rlimit saved{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &saved), 0);
    const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = saved;
    small.rlim_cur = 16;
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
    QString error;
    const Status status =
        ParameterFile::save(m_schema, QStringLiteral("elab"), sampleSet(), path, &error);
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previousHandler);
    QCOMPARE(status, Status::FileError);
    // The system's reason, not Qt's "Writing canceled by application".
    QVERIFY2(error == QStringLiteral("Cannot write %1: %2").arg(path, qt_error_string(EFBIG)),
             qPrintable(error));
    QVERIFY(file.open(QIODevice::ReadOnly));
    QCOMPARE(file.readAll(), old);
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::Files),
             QStringList{QStringLiteral("machine.json")});
}

void TestParameterFile::save_overwrites_noTemporaryFilesLeft()
{
    const QString path = m_dir->filePath(QStringLiteral("machine.json"));
    QString error;
    ParameterSet first = sampleSet();
    first[QStringLiteral("drive-power")].global = qint64(10);
    QCOMPARE(ParameterFile::save(m_schema, QStringLiteral("elab"), first, path, &error),
             Status::Ok);
    QCOMPARE(ParameterFile::save(m_schema, QStringLiteral("elab"), sampleSet(), path, &error),
             Status::Ok);
    ParameterSet loaded;
    QCOMPARE(ParameterFile::load(m_schema, QStringLiteral("elab"), kFileXyz, path, &loaded, &error),
             Status::Ok);
    QCOMPARE(loaded, sampleSet());
    QCOMPARE(QDir(m_dir->path()).entryList(QDir::Files),
             QStringList{QStringLiteral("machine.json")});
}

STEPDECK_TEST_GUILESS_MAIN(TestParameterFile)
#include "tst_parameterfile.moc"
