// WritePreview: the confirmation before a setup write shows every value old -> new (issue 31).
// The old value is what the device last reported; one written since and not read back, one
// never read and one the protocol cannot read say so, never a default in their place.
#include "TestMain.h"
#include "TestSupport.h"
#include "model/ModelInfo.h"
#include "protocols/Registry.h"
#include "setup/WritePreview.h"
#include <QTableWidget>
#include <QtTest>

using namespace stepdeck;
using ui::WritePreview;

namespace {
const QString kCurrent = QStringLiteral("phase-current");

ParameterSet perAxis(const QString& name, Axis axis, const QVariant& v)
{
    ParameterValue value;
    value.perAxis.insert(axis, v);
    return {{name, value}};
}

ParameterSchema schemaOf(const char* model)
{
    return findModel(QString::fromLatin1(model))->schema;
}

WritePreview::Row onlyRow(const ParameterSet& set, const WritePreview::OnDevice& onDevice,
                          const char* model = "nanotec")
{
    const QList<WritePreview::Row> rows =
        WritePreview::rows(schemaOf(model), set, {{Axis::Y, 2}}, onDevice);
    return rows.size() == 1 ? rows.first() : WritePreview::Row{};
}
} // namespace

class TestWritePreview : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void rows_readBack_showsOldAndNew();
    void rows_neverRead_oldUnknown();
    void rows_writtenNotReadBack_saysSo();
    void rows_writeOnlyParameter_cannotBeReadBack();
    void dialog_columns_oldBeforeNew();
    void rows_valueWithoutUnit_saysNoUnit();
};

void TestWritePreview::rows_readBack_showsOldAndNew()
{
    const ParameterSet read = perAxis(kCurrent, Axis::Y, 50);
    const WritePreview::Row row = onlyRow(perAxis(kCurrent, Axis::Y, 70), {read, read});
    QCOMPARE(row.drive, QStringLiteral("Drive 2 (Y)"));
    QCOMPARE(row.old, QStringLiteral("50"));
    QCOMPARE(row.value, QStringLiteral("70"));
}

void TestWritePreview::rows_neverRead_oldUnknown()
{
    const WritePreview::Row row = onlyRow(perAxis(kCurrent, Axis::Y, 70), {});
    QCOMPARE(row.old, QStringLiteral("unknown (not read)"));
    QCOMPARE(row.value, QStringLiteral("70"));
}

void TestWritePreview::rows_writtenNotReadBack_saysSo()
{
    // Known because it was written (drives echo values they then ignore): not a read value.
    const WritePreview::Row row =
        onlyRow(perAxis(kCurrent, Axis::Y, 70), {{}, perAxis(kCurrent, Axis::Y, 60)});
    QCOMPARE(row.old, QStringLiteral("60 (written, not read back)"));
}

void TestWritePreview::rows_writeOnlyParameter_cannotBeReadBack()
{
    const WritePreview::Row row =
        onlyRow(perAxis(QStringLiteral("run-current"), Axis::Y, 80), {}, "emis");
    QCOMPARE(row.old, QStringLiteral("unknown (cannot be read back)"));
    QCOMPARE(row.value, QStringLiteral("80"));
}

void TestWritePreview::dialog_columns_oldBeforeNew()
{
    const ParameterSet read = perAxis(kCurrent, Axis::Y, 50);
    WritePreview dialog(schemaOf("nanotec"), perAxis(kCurrent, Axis::Y, 70), {{Axis::Y, 2}},
                        {read, read}, {});
    QTableWidget* table = dialog.table();
    QCOMPARE(dialog.rowCount(), 1);
    QCOMPARE(table->horizontalHeaderItem(2)->text(), QStringLiteral("Old"));
    QCOMPARE(table->horizontalHeaderItem(3)->text(), QStringLiteral("New"));
    QCOMPARE(table->item(0, 2)->text(), QStringLiteral("50"));
    QCOMPARE(table->item(0, 3)->text(), QStringLiteral("70"));
}

// The E-LAB manual gives the acceleration no unit: the preview says so, as the setup page does
// (issue 31 leftover: the preview's unit column was empty).
void TestWritePreview::rows_valueWithoutUnit_saysNoUnit()
{
    ParameterValue value;
    value.global = 1200;
    const QList<WritePreview::Row> rows =
        WritePreview::rows(schemaOf("elab"), {{QStringLiteral("acceleration"), value}}, {}, {});
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows.first().unit, QStringLiteral("(no unit)"));
    QCOMPARE(rows.first().value, QStringLiteral("1200"));
}

STEPDECK_TEST_MAIN(TestWritePreview)
#include "tst_writepreview.moc"
