// Records page: all 32 records of a drive in a table, a record edited and written (stored and
// verified by the adapter), and the error memory decoded.
#include "../NanotecUiFixture.h"
#include "TestMain.h"
#include "records/RecordsPage.h"
#include <QComboBox>
#include <QCompleter>
#include <QDockWidget>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSpinBox>
#include <QTableWidget>

using namespace stepdeck;
using namespace stepdeck::test;

class TestRecordsPage : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void readAll_fills32Records();
    void writeRecord_editedValueStored();
    void errorMemory_decoded();
    void choiceCell_editedFromSchemaChoices();
    void driveChoice_manyDrives_foundByTypedName();

private:
    ui::RecordsPage* page() const { return m_f->window->recordsPage(); }
    std::unique_ptr<NanotecUiFixture> m_f;
};

void TestRecordsPage::init()
{
    QSettings().clear();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec());
    QVERIFY(!m_f->window->findChild<QDockWidget*>(QStringLiteral("recordsDock"))->isHidden());
    QCOMPARE(page()->axisCombo()->count(), 3);
}

void TestRecordsPage::readAll_fills32Records()
{
    page()->axisCombo()->setCurrentIndex(1); // Y, drive 2
    page()->readAll();
    QVERIFY(page()->busy());
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QVERIFY2(!page()->stateText().startsWith(QStringLiteral("Failed")),
             qPrintable(page()->stateText()));
    QCOMPARE(page()->recordTable()->rowCount(), 32);
    QVERIFY(page()->columns().contains(QStringLiteral("max-frequency")));
    const int col = int(page()->columns().indexOf(QStringLiteral("max-frequency")));
    for (int row = 0; row < 32; ++row)
        QVERIFY2(page()->recordTable()->item(row, col), qPrintable(QString::number(row)));
}

void TestRecordsPage::writeRecord_editedValueStored()
{
    page()->readAll();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    const int col = int(page()->columns().indexOf(QStringLiteral("max-frequency")));
    QVERIFY(col >= 0);
    page()->recordSpin()->setValue(5);
    page()->recordTable()->item(4, col)->setData(Qt::EditRole, 1234);
    page()->writeRecord();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QVERIFY2(page()->stateText().contains(QStringLiteral("verified")),
             qPrintable(page()->stateText()));

    // Read back from the drive: the EEPROM holds the new value.
    page()->recordTable()->item(4, col)->setData(Qt::EditRole, 0);
    page()->readAll();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QCOMPARE(page()->recordTable()->item(4, col)->data(Qt::EditRole).toLongLong(), 1234);
}

void TestRecordsPage::errorMemory_decoded()
{
    page()->readErrorMemory();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QVERIFY2(!page()->stateText().startsWith(QStringLiteral("Failed")),
             qPrintable(page()->stateText()));
    QVERIFY(page()->errorTable()->rowCount() > 0);
    QVERIFY(!page()->errorTable()->item(0, 2)->text().isEmpty()); // decoded name
}

void TestRecordsPage::choiceCell_editedFromSchemaChoices()
{
    page()->readAll();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    const int col = int(page()->columns().indexOf(QStringLiteral("direction")));
    QVERIFY(col >= 0);
    QTableWidget* table = page()->recordTable();
    const QModelIndex index = table->model()->index(2, col);
    QAbstractItemDelegate* delegate = table->itemDelegate();
    std::unique_ptr<QWidget> editor(delegate->createEditor(table, {}, index));
    auto* combo = qobject_cast<QComboBox*>(editor.get());
    QVERIFY(combo);
    QCOMPARE(combo->count(), 2); // left, right (6.12)
    combo->setCurrentIndex(combo->findData(QStringLiteral("right")));
    delegate->setModelData(combo, table->model(), index);
    QCOMPARE(index.data(Qt::EditRole).toString(), QStringLiteral("right"));

    page()->recordSpin()->setValue(3);
    page()->writeRecord();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QVERIFY2(page()->stateText().contains(QStringLiteral("verified")),
             qPrintable(page()->stateText()));
    page()->readAll();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QCOMPARE(table->item(2, col)->data(Qt::EditRole).toString(), QStringLiteral("right"));
}

// Issue 32, step 5: on a bus of many drives the drive is found by typing part of its name;
// the records are then read from that drive (its address in the frames at the simulator), and
// text typed without picking goes back to the chosen drive's name.
void TestRecordsPage::driveChoice_manyDrives_foundByTypedName()
{
    QVERIFY(!page()->axisCombo()->isEditable()); // three drives: a plain list
    m_f.reset();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec(NanotecUiFixture::sixNamedDrives()));
    QComboBox* combo = page()->axisCombo();
    QTRY_COMPARE(combo->count(), 6);
    QVERIFY(combo->isEditable());
    QCompleter* completer = combo->completer();
    completer->setCompletionPrefix(QStringLiteral("TACK"));
    QCOMPARE(completer->completionCount(), 1);
    QCOMPARE(completer->currentCompletion(), QStringLiteral("Axis stacker"));
    Q_EMIT completer->activated(completer->currentIndex()); // as the popup does on a pick
    QCOMPARE(combo->currentData().toString(), QStringLiteral("axis6"));

    combo->setEditText(QStringLiteral("gat"));
    Q_EMIT combo->lineEdit()->editingFinished(); // left without picking
    QCOMPARE(combo->currentText(), QStringLiteral("Axis stacker"));

    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    page()->readAll();
    QTRY_VERIFY_WITH_TIMEOUT(!page()->busy(), 20000);
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    int toStacker = 0;
    int toFeeder = 0;
    // Status polls go to every drive; a record read ("Z<n>|", 5.2) to the chosen one.
    const QRegularExpression recordRead(QStringLiteral("^#(\\d+)Z\\d+\\|"));
    for (const QByteArray& f : frames) {
        const QRegularExpressionMatch m = recordRead.match(QString::fromLatin1(f));
        toStacker += m.hasMatch() && m.captured(1) == QLatin1String("6") ? 1 : 0;
        toFeeder += m.hasMatch() && m.captured(1) == QLatin1String("1") ? 1 : 0;
    }
    QVERIFY2(toStacker >= 32, qPrintable(QString::number(toStacker)));
    QCOMPARE(toFeeder, 0);
}

STEPDECK_TEST_MAIN(TestRecordsPage)
#include "tst_recordspage.moc"
