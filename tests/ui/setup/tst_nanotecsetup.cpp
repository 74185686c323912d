// The setup page on a Nanotec bus (values read back per drive): a value that could not be
// read is shown as unknown, never as a default; a one-field edit with a silent drive on the
// bus writes that one value and nothing else; the preview lists exactly what will be sent,
// per drive, before anything is sent. Checked at the simulated bus (frames it received).
#include "../NanotecUiFixture.h"
#include "TestMain.h"
#include "setup/ParameterField.h"
#include "setup/SetupPage.h"
#include "setup/WritePreview.h"
#include <QLineEdit>
#include <QPushButton>
#include <QTableWidget>

using namespace stepdeck;
using namespace stepdeck::test;

namespace {
// Host frames that change something: not the status sweep ('$', 'C') and not reads ('Z...').
QList<QByteArray> writes(const QList<QByteArray>& frames)
{
    QList<QByteArray> out;
    for (const QByteArray& f : frames) {
        qsizetype i = 1; // after '#'
        while (i < f.size() &&
               (std::isdigit(static_cast<unsigned char>(f.at(i))) || f.at(i) == '*'))
            ++i;
        const char cmd = i < f.size() ? f.at(i) : '\0';
        if (cmd != 'Z' && cmd != '$' && cmd != 'C')
            out << f.trimmed();
    }
    return out;
}
} // namespace

class TestNanotecSetup : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void connect_readsDeviceValues_notDefaults();
    void silentDrive_failedRead_valuesUnknown();
    void oneFieldEdit_withSilentDrive_previewAndWriteOnlyThatValue();
    void preview_cancelled_sendsNothing();
    void writeAndVerify_saysWhatWasReadBack();
    void preview_nanotec_showsOldAndNew();

private:
    ui::SetupPage* page() const { return m_f->window->setupPage(); }
    ui::ParameterField* current(Axis axis) const
    {
        return page()->field(QStringLiteral("phase-current"), axis);
    }
    void silenceDrive2AndRead();
    QString previewOld(const QString& typed); // types into X, opens the preview: its old value
    std::unique_ptr<NanotecUiFixture> m_f;
};

void TestNanotecSetup::init()
{
    QSettings().clear();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec());
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Read ")), 15000);
}

void TestNanotecSetup::connect_readsDeviceValues_notDefaults()
{
    // Drive 2 holds 77 % (the schema default is 50 %): the form shows the drive's value.
    m_f->session->sendRaw(QByteArrayLiteral("#2i77\r"));
    page()->read();
    QTRY_COMPARE_WITH_TIMEOUT(current(Axis::Y)->value().toLongLong(), qint64(77), 15000);
    for (Axis a : {Axis::X, Axis::Y, Axis::Z}) {
        QVERIFY(!current(a)->isUnknown());
        QVERIFY(current(a)->baseline().isValid());
        QVERIFY(!current(a)->isChanged());
    }
    QVERIFY(page()->changedValues().isEmpty());
}

void TestNanotecSetup::silenceDrive2AndRead()
{
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->setDriveSilent(2, true); }));
    page()->read();
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Read failed")),
                             20000);
}

void TestNanotecSetup::silentDrive_failedRead_valuesUnknown()
{
    silenceDrive2AndRead();
    ui::ParameterField* y = current(Axis::Y);
    QVERIFY(y->isUnknown());
    QVERIFY(y->lineEdit()->text().isEmpty()); // not the default "50"
    QCOMPARE(y->lineEdit()->property("fieldState").toString(), QStringLiteral("unknown"));
    QVERIFY(y->isValid()); // unknown is no error: the rest can still be written
    QVERIFY(page()->writeButton()->isEnabled());
    QVERIFY(!y->isChanged());
    QVERIFY(page()->changedValues().isEmpty()); // nothing is written without a choice
}

void TestNanotecSetup::oneFieldEdit_withSilentDrive_previewAndWriteOnlyThatValue()
{
    silenceDrive2AndRead();
    QLineEdit* edit = current(Axis::X)->lineEdit();
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("60"));
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    page()->writeButton()->click();
    ui::WritePreview* preview = page()->openPreview();
    QVERIFY(preview);
    QVERIFY(!preview->isModal());
    QCOMPARE(preview->rowCount(), 1); // exactly what will be sent
    QCOMPARE(preview->table()->item(0, 0)->text(), QStringLiteral("Drive 1 (X)"));
    QCOMPARE(preview->table()->item(0, 3)->text(), QStringLiteral("60")); // Old, New
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    QVERIFY(writes(frames).isEmpty()); // nothing before the technician says so
    preview->accept();
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    QCOMPARE(writes(frames), QList<QByteArray>{QByteArray("#1i60")});
}

void TestNanotecSetup::preview_cancelled_sendsNothing()
{
    QLineEdit* edit = current(Axis::Z)->lineEdit();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("70"));
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    page()->writeButton()->click();
    QVERIFY(page()->openPreview());
    QVERIFY(!page()->isEnabled()); // the page waits for the answer
    page()->openPreview()->reject();
    QTRY_VERIFY(page()->isEnabled());
    QVERIFY(page()->messageText().contains(QStringLiteral("cancelled")));
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    QVERIFY(writes(frames).isEmpty());
}

void TestNanotecSetup::writeAndVerify_saysWhatWasReadBack()
{
    // Issue 16: "Write & verify" names what the drives were asked for again and reported back.
    QLineEdit* edit = current(Axis::Y)->lineEdit();
    edit->selectAll();
    QTest::keyClicks(edit, QStringLiteral("66"));
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    QVERIFY(page()->write(true, false));
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    const QString label = current(Axis::Y)->spec().label; // English: no translator installed
    QCOMPARE(page()->messageText(),
             QStringLiteral("Written and verified by reading back: %1 (Y).").arg(label));
    // It was read back: the drive received the read of 'i' after the write.
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    const qsizetype written = frames.indexOf(QByteArray("#2i66\r"));
    QVERIFY2(written >= 0, frames.join(' ').constData());
    QVERIFY(frames.mid(written).contains(QByteArray("#2Zi\r")));
}

QString TestNanotecSetup::previewOld(const QString& typed)
{
    if (!QTest::qWaitFor([this] { return page()->isEnabled(); }, 5000)) // a dialog closing
        return QStringLiteral("page disabled");
    QLineEdit* edit = current(Axis::X)->lineEdit();
    edit->setFocus();
    edit->selectAll();
    QTest::keyClicks(edit, typed);
    page()->writeButton()->click();
    ui::WritePreview* preview = page()->openPreview();
    if (!preview || preview->rowCount() != 1)
        return QStringLiteral("no preview of one row");
    if (preview->table()->item(0, 3)->text() != typed)
        return QStringLiteral("new value %1").arg(preview->table()->item(0, 3)->text());
    return preview->table()->item(0, 2)->text();
}

void TestNanotecSetup::preview_nanotec_showsOldAndNew()
{
    // Issue 31: old -> new, the old value being what drive 1 last reported.
    m_f->session->sendRaw(QByteArrayLiteral("#1i44\r"));
    page()->read();
    QTRY_COMPARE_WITH_TIMEOUT(current(Axis::X)->value().toLongLong(), qint64(44), 15000);
    QCOMPARE(previewOld(QStringLiteral("60")), QStringLiteral("44"));
    page()->openPreview()->accept();
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    // A plain write is not read back (drives echo values they then ignore): it says so.
    QCOMPARE(previewOld(QStringLiteral("61")), QStringLiteral("60 (written, not read back)"));
    page()->openPreview()->reject();
    // Write & verify reads it back: the value the drive reported again.
    QVERIFY(page()->write(true, false));
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    QCOMPARE(previewOld(QStringLiteral("62")), QStringLiteral("61"));
    page()->openPreview()->reject();
}

STEPDECK_TEST_MAIN(TestNanotecSetup)
#include "tst_nanotecsetup.moc"
