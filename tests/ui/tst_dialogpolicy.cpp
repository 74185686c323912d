// Issue 7, rule 5: no dialog may block STOP and PANIC. Every dialog under ui/ goes through
// common/Dialogs.h (non-modal, non-native, the page it belongs to disabled meanwhile); this
// test rejects the calls that open a modal or native dialog, in every source file, so pages
// added later cannot bring one back.
#include "TestMain.h"
#include <QDirIterator>
#include <QFile>
#include <QRegularExpression>
#include <QtTest>

class TestDialogPolicy : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void uiSources_openNoModalOrNativeDialog();
    void pattern_catchesModalCalls_data();
    void pattern_catchesModalCalls();

private:
    static const QList<QPair<QRegularExpression, QString>>& rules();
    static QStringList violations(const QString& source);
};

const QList<QPair<QRegularExpression, QString>>& TestDialogPolicy::rules()
{
    static const QList<QPair<QRegularExpression, QString>> list{
        {QRegularExpression(QStringLiteral(R"((\.|->)exec\(\s*\))")),
         QStringLiteral("exec() runs a modal loop")},
        // open() of a dialog or box (a link's open() is fine)
        {QRegularExpression(QStringLiteral(R"(\w*([dD]ialog|[bB]ox)\w*(\.|->)open\(\s*\))")),
         QStringLiteral("QDialog::open() is window-modal")},
        {QRegularExpression(QStringLiteral(R"(QFileDialog::get\w+)")),
         QStringLiteral("static file dialogs are modal and native")},
        {QRegularExpression(
             QStringLiteral(R"(QMessageBox::(information|warning|critical|question|about)\s*\()")),
         QStringLiteral("static message boxes are modal")},
        {QRegularExpression(QStringLiteral(R"(aboutQt)")),
         QStringLiteral("QMessageBox::aboutQt is modal")},
        {QRegularExpression(QStringLiteral(R"(QInputDialog::get\w+)")),
         QStringLiteral("static input dialogs are modal")},
        {QRegularExpression(QStringLiteral(R"(setModal\(\s*true)")),
         QStringLiteral("modal dialogs block STOP and PANIC")},
        {QRegularExpression(QStringLiteral(R"(Qt::(Application|Window)Modal)")),
         QStringLiteral("modal dialogs block STOP and PANIC")},
    };
    return list;
}

QStringList TestDialogPolicy::violations(const QString& source)
{
    QStringList out;
    const QStringList lines = source.split(QLatin1Char('\n'));
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines.at(i).section(QStringLiteral("//"), 0, 0);
        for (const auto& [pattern, why] : rules()) {
            if (pattern.match(line).hasMatch())
                out << QStringLiteral("line %1: %2 (%3)").arg(i + 1).arg(line.trimmed(), why);
        }
    }
    return out;
}

void TestDialogPolicy::uiSources_openNoModalOrNativeDialog()
{
    const QString root = QStringLiteral(STEPDECK_SOURCE_DIR "/ui");
    QDirIterator it(root, {QStringLiteral("*.cpp"), QStringLiteral("*.h")}, QDir::Files,
                    QDirIterator::Subdirectories);
    int files = 0;
    QStringList problems;
    while (it.hasNext()) {
        const QString path = it.next();
        QFile file(path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(path));
        ++files;
        for (const QString& v : violations(QString::fromUtf8(file.readAll())))
            problems << QStringLiteral("%1 %2").arg(path.mid(root.size() + 1), v);
    }
    QVERIFY(files > 20); // the sources were found
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

void TestDialogPolicy::pattern_catchesModalCalls_data()
{
    QTest::addColumn<QString>("line");
    QTest::addColumn<bool>("rejected");
    QTest::newRow("exec") << QStringLiteral("    dialog.exec();") << true;
    QTest::newRow("exec ptr") << QStringLiteral("    const int c = dialog->exec();") << true;
    QTest::newRow("open") << QStringLiteral("    dialog->open();") << true;
    QTest::newRow("session open") << QStringLiteral("    m_session->open();") << false;
    QTest::newRow("file open with mode")
        << QStringLiteral("file.open(QIODevice::ReadOnly)") << false;
    QTest::newRow("getSaveFileName")
        << QStringLiteral("QFileDialog::getSaveFileName(this, t, n, f);") << true;
    QTest::newRow("warning") << QStringLiteral("QMessageBox::warning(this, t, e);") << true;
    QTest::newRow("icon enum") << QStringLiteral(
                                      "dialogs::message(this, QMessageBox::Warning, t, e);")
                               << false;
    QTest::newRow("aboutQt") << QStringLiteral("connect(a, &QAction::triggered, qApp, "
                                               "&QApplication::aboutQt);")
                             << true;
    QTest::newRow("modality") << QStringLiteral("d->setWindowModality(Qt::WindowModal);") << true;
    QTest::newRow("comment") << QStringLiteral("// never call dialog.exec() here") << false;
}

void TestDialogPolicy::pattern_catchesModalCalls()
{
    QFETCH(QString, line);
    QFETCH(bool, rejected);
    QCOMPARE(!violations(line).isEmpty(), rejected);
}

STEPDECK_TEST_MAIN(TestDialogPolicy)
#include "tst_dialogpolicy.moc"
