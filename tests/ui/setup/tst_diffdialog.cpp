// DiffDialog: what a loaded parameter file changes; "Changes only" (on at first) hides the
// rows the file leaves as they are (issue 31).
#include "TestMain.h"
#include "TestSupport.h"
#include "model/ModelInfo.h"
#include "protocols/Registry.h"
#include "setup/DiffDialog.h"
#include <QCheckBox>
#include <QTableWidget>
#include <QtTest>

using namespace stepdeck;
using ui::DiffDialog;

namespace {
ParameterSet currents(qint64 x, qint64 y, qint64 z)
{
    ParameterValue v;
    v.perAxis = {{Axis::X, x}, {Axis::Y, y}, {Axis::Z, z}};
    return {{QStringLiteral("phase-current"), v}};
}

QList<DiffDialog::Row> oneChange()
{
    // The file changes Y only; X and Z are as in the form.
    return DiffDialog::compare(findModel(QStringLiteral("nanotec"))->schema, currents(50, 50, 50),
                               currents(50, 70, 50));
}
} // namespace

class TestDiffDialog : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void changesOnly_defaultOn_hidesUnchangedRows();
    void changesOnly_off_showsEveryRow();
};

void TestDiffDialog::changesOnly_defaultOn_hidesUnchangedRows()
{
    DiffDialog dialog(oneChange(), QStringLiteral("drives.json"));
    QCOMPARE(dialog.table()->rowCount(), 3);
    QCOMPARE(dialog.changedCount(), 1);
    QVERIFY(dialog.changesOnlyBox()->isChecked());
    QCOMPARE(dialog.changesOnlyBox()->text(), QStringLiteral("Changes only"));
    QCOMPARE(dialog.visibleRowCount(), 1);
    for (int r = 0; r < dialog.table()->rowCount(); ++r) {
        const bool isY = dialog.table()->item(r, 1)->text() == QStringLiteral("Y");
        QCOMPARE(dialog.table()->isRowHidden(r), !isY);
    }
}

void TestDiffDialog::changesOnly_off_showsEveryRow()
{
    DiffDialog dialog(oneChange(), QStringLiteral("drives.json"));
    dialog.changesOnlyBox()->click();
    QVERIFY(!dialog.changesOnlyBox()->isChecked());
    QCOMPARE(dialog.visibleRowCount(), 3);
    dialog.changesOnlyBox()->click(); // and back
    QCOMPARE(dialog.visibleRowCount(), 1);
}

STEPDECK_TEST_MAIN(TestDiffDialog)
#include "tst_diffdialog.moc"
