// File dialogs remember the last folder (issue 11): per dialog key, a key used for the first
// time starts where any file dialog was last used, a folder that no longer exists is not
// offered, and every dialog stays non-native and non-modal (issue 7, rule 5).
#include "TestMain.h"
#include "common/Dialogs.h"
#include <QApplication>
#include <QFileDialog>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QtTest>

using namespace stepdeck::ui;

class TestDialogs : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase();
    void init() { QSettings().clear(); }
    void chosenFile_folderRemembered_perKey_andForNewKeys();
    void vanishedFolder_notOffered();
    void documentsMissing_createdAndOffered();
    void documentsCannotBeMade_homeOffered();

private:
    QTemporaryDir m_home;
};

void TestDialogs::initTestCase()
{
    // A home of the test's own: the default folder may be created (issue 16), never in the
    // home of whoever runs the tests.
    QVERIFY(m_home.isValid());
    qputenv("HOME", QFile::encodeName(m_home.path()));
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("StepDeckTest"));
    QCoreApplication::setApplicationName(QStringLiteral("StepDeckDialogsTest"));
}

void TestDialogs::chosenFile_folderRemembered_perKey_andForNewKeys()
{
    QTemporaryDir first;
    QTemporaryDir second;
    QWidget window;
    auto* page = new QWidget(&window);
    (new QVBoxLayout(&window))->addWidget(page);
    window.show();
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), documents);

    QString chosen;
    QFileDialog* dialog = dialogs::saveFile(
        page, QStringLiteral("parameters"), QStringLiteral("Save"), QStringLiteral("p.json"),
        QStringLiteral("JSON (*.json)"), [&chosen](const QString& path) { chosen = path; });
    QVERIFY(dialog->testOption(QFileDialog::DontUseNativeDialog));
    QVERIFY(!dialog->isModal());
    QVERIFY(!page->isEnabled()); // its page waits, the window (STOP, PANIC) does not
    dialog->selectFile(first.filePath(QStringLiteral("p.json")));
    static_cast<QDialog*>(dialog)->accept(); // the Save button
    QCOMPARE(chosen, first.filePath(QStringLiteral("p.json")));
    QTRY_VERIFY(page->isEnabled());
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), first.path());
    // Another dialog used for the first time starts there too ...
    QCOMPARE(dialogs::lastFolder(QStringLiteral("traffic")), first.path());
    QFileDialog* open = dialogs::openFile(page, QStringLiteral("traffic"), QStringLiteral("Open"),
                                          QStringLiteral("*"), {});
    QCOMPARE(open->directory().absolutePath(), QDir(first.path()).absolutePath());
    open->reject();
    // ... and once it has a folder of its own, each keeps its own.
    dialogs::rememberFolder(QStringLiteral("traffic"), second.path());
    QCOMPARE(dialogs::lastFolder(QStringLiteral("traffic")), second.path());
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), first.path());
    QCOMPARE(dialogs::lastFolder(QStringLiteral("charts")), second.path()); // the newest
}

void TestDialogs::vanishedFolder_notOffered()
{
    QTemporaryDir kept;
    QString gone;
    {
        QTemporaryDir removed;
        gone = removed.path();
        dialogs::rememberFolder(QStringLiteral("charts"), kept.path());
        dialogs::rememberFolder(QStringLiteral("parameters"), gone);
        QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), gone);
    }
    QVERIFY(!QDir(gone).exists());
    // Its own folder is gone; the last folder of all is gone too (it was the same): Documents.
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")),
             QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
    dialogs::rememberFolder(QStringLiteral("charts"), kept.path());
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), kept.path());
}

void TestDialogs::documentsMissing_createdAndOffered()
{
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QVERIFY2(documents.startsWith(m_home.path()), qPrintable(documents));
    QDir(documents).removeRecursively();
    QVERIFY(!QDir(documents).exists());
    // A save dialog opened for the first time starts in Documents, which now exists: the
    // suggested path (e.g. ~/Documents/elab-parameters.json) can be written.
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")), documents);
    QVERIFY(QFileInfo(documents).isDir());
    QFile file(QDir(documents).filePath(QStringLiteral("elab-parameters.json")));
    QVERIFY2(file.open(QIODevice::WriteOnly), qPrintable(file.errorString()));
}

void TestDialogs::documentsCannotBeMade_homeOffered()
{
    const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    QDir(documents).removeRecursively();
    QFile blocker(documents); // a file where the folder should be: no folder can be made
    QVERIFY(blocker.open(QIODevice::WriteOnly));
    blocker.close();
    QCOMPARE(dialogs::lastFolder(QStringLiteral("parameters")),
             QFileInfo(m_home.path()).absoluteFilePath());
    QVERIFY(QFile::remove(documents));
}

STEPDECK_TEST_MAIN(TestDialogs)
#include "tst_dialogs.moc"
