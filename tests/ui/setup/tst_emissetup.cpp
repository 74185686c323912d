// The setup page on an EMIS SMC-IC4 (in-process simulator): the board cannot read any working
// value back, so nothing on the page may claim a verification (issue 31): no Write & verify
// button, and a write asked to verify says it verified nothing, from the first message on.
#include "../EmisUiFixture.h"
#include "TestMain.h"
#include "setup/SetupPage.h"
#include <QPushButton>

using namespace stepdeck;
using namespace stepdeck::test;

class TestEmisSetup : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { isolateSettings(); }
    void init();
    void cleanup() { m_f.reset(); }

    void writeVerify_emisWriteOnly_noVerifyButton();
    void write_emisWriteOnly_saysNotVerified();

private:
    ui::SetupPage* page() const { return m_f->window->setupPage(); }
    std::unique_ptr<EmisUiFixture> m_f;
};

void TestEmisSetup::init()
{
    QSettings().clear();
    m_f = std::make_unique<EmisUiFixture>();
    m_f->window->show();
    QVERIFY(m_f->connectEmis());
}

void TestEmisSetup::writeVerify_emisWriteOnly_noVerifyButton()
{
    // Write is the one write on a controller that cannot read back: a "Write & verify" button
    // would promise a comparison the board cannot make.
    QVERIFY(page()->writeButton()->isVisibleTo(page()));
    QVERIFY(page()->writeButton()->isEnabled());
    QVERIFY(!page()->writeVerifyButton()->isVisibleTo(page()));
    QVERIFY(!page()->readButton()->isVisibleTo(page()));
}

void TestEmisSetup::write_emisWriteOnly_saysNotVerified()
{
    // A verifying write asked for anyway (File menu, scripts) never says it verifies.
    QVERIFY(page()->write(true, false));
    QVERIFY2(!page()->messageText().contains(QStringLiteral("verif")),
             qPrintable(page()->messageText()));
    QVERIFY(page()->messageText().startsWith(QStringLiteral("Writing")));
    QTRY_VERIFY_WITH_TIMEOUT(page()->messageText().startsWith(QStringLiteral("Written")), 10000);
    QVERIFY2(page()->messageText().contains(QStringLiteral("Nothing could be verified")),
             qPrintable(page()->messageText()));
    QVERIFY(!page()->messageText().contains(QStringLiteral("verified by")));
}

STEPDECK_TEST_MAIN(TestEmisSetup)
#include "tst_emissetup.moc"
