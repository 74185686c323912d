// A Nanotec drive's position error in the GUI (issue 16): the message names the window's own
// "Reset position error" button (not the CLI's `reset-position-error`), and that button
// clears the error at the simulated drive selected in the drive table.
#include "../NanotecUiFixture.h"
#include "TestMain.h"
#include "drives/DrivePanel.h"
#include "drives/PositionErrorResetButton.h"
#include "protocols/nanotec/NanotecCodec.h"
#include <QTableView>

using namespace stepdeck;
using namespace stepdeck::test;

class TestPositionErrorReset : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void positionError_messageNamesTheButton_buttonClearsIt();

private:
    bool driveHasError(int address)
    {
        bool error = false;
        m_f->withBus([&](nanotec::NanotecSimulator* s) {
            error = nanotec::decodeStatus(s->drive(address)->statusWord()).positionError;
        });
        return error;
    }
    std::unique_ptr<NanotecUiFixture> m_f;
};

void TestPositionErrorReset::init()
{
    QSettings().clear();
    m_f = std::make_unique<NanotecUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectNanotec());
}

void TestPositionErrorReset::positionError_messageNamesTheButton_buttonClearsIt()
{
    ui::DrivePanel* panel = m_f->window->drivePanel();
    ui::PositionErrorResetButton* button = panel->resetPositionErrorButton();
    QVERIFY(button);
    QVERIFY(!button->isEnabled()); // no drive selected
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->drive(2)->injectPositionError(); }));
    QTRY_VERIFY_WITH_TIMEOUT(m_f->window->lastError().contains(QStringLiteral("position error")),
                             5000);
    const QString message = m_f->window->lastError();
    QVERIFY2(message.contains(QStringLiteral("\u201c%1\u201d button").arg(button->text())),
             qPrintable(message));
    QVERIFY2(!message.contains(QStringLiteral("reset-position-error")), qPrintable(message));

    QTRY_COMPARE(panel->driveTable()->model()->rowCount(), 3);
    panel->driveTable()->selectRow(1); // drive 2, axis Y
    QTRY_VERIFY(button->isEnabled());
    QVERIFY(m_f->withBus([](nanotec::NanotecSimulator* s) { s->clearReceivedFrames(); }));
    button->click();
    QTRY_VERIFY_WITH_TIMEOUT(!driveHasError(2), 5000);
    QList<QByteArray> frames;
    QVERIFY(m_f->withBus([&](nanotec::NanotecSimulator* s) { frames = s->receivedFrames(); }));
    QVERIFY(frames.contains(QByteArray("#2D\r")));
    QVERIFY(!frames.contains(QByteArray("#1D\r")) && !frames.contains(QByteArray("#3D\r")));
    QTRY_VERIFY(panel->scanState().contains(QStringLiteral("axis Y reset")));
}

STEPDECK_TEST_MAIN(TestPositionErrorReset)
#include "tst_positionerrorreset.moc"
