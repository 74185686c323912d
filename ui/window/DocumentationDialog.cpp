#include "DocumentationDialog.h"
#include <QDialogButtonBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QImage>
#include <QListWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QVBoxLayout>

namespace stepdeck::ui {

QList<DocumentationDialog::Document> DocumentationDialog::documents()
{
    // The paths as in the source tree (ui/CMakeLists.txt embeds them with that base), so the
    // README's "docs/machines.md" and "docs/screenshots/..." resolve as they do on GitHub.
    return {
        {tr("Overview and quick start"), QUrl(QStringLiteral("qrc:/docs/README.md"))},
        {tr("Machines"), QUrl(QStringLiteral("qrc:/docs/docs/machines.md"))},
        {tr("Programs (G-code)"), QUrl(QStringLiteral("qrc:/docs/docs/programs.md"))},
        {tr("Command line"), QUrl(QStringLiteral("qrc:/docs/docs/cli.md"))},
    };
}

DocumentationDialog::DocumentationDialog(QWidget* parent)
    : QDialog(parent), m_list(new QListWidget(this)), m_browser(new QTextBrowser(this))
{
    setObjectName(QStringLiteral("documentation"));
    setWindowTitle(tr("StepDeck documentation"));
    m_list->setObjectName(QStringLiteral("documentationList"));
    m_browser->setObjectName(QStringLiteral("documentationText"));
    m_browser->setOpenLinks(true);
    m_browser->setOpenExternalLinks(true); // a web link goes to the system's browser
    m_browser->viewport()->installEventFilter(this);
    for (const Document& d : documents())
        m_list->addItem(d.title);
    m_list->setMaximumWidth(m_list->sizeHintForColumn(0) + 2 * m_list->frameWidth() + 24);
    connect(m_list, &QListWidget::currentRowChanged, this, &DocumentationDialog::showDocument);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* row = new QHBoxLayout;
    row->addWidget(m_list);
    row->addWidget(m_browser, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(row, 1);
    layout->addWidget(buttons);
    resize(960, 640);
    m_list->setCurrentRow(0);
}

void DocumentationDialog::showDocument(int document)
{
    const QList<Document> docs = documents();
    if (document < 0 || document >= docs.size())
        return;
    m_browser->setSource(docs.at(document).source, QTextDocument::MarkdownResource);
    fitImages();
}

bool DocumentationDialog::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_browser->viewport() && event->type() == QEvent::Resize)
        fitImages();
    return QDialog::eventFilter(watched, event);
}

// A screenshot 1366 px wide would make the page scroll sideways: each image is shown at most as
// wide as the page, its height in proportion.
void DocumentationDialog::fitImages()
{
    const double room = qMax(200, m_browser->viewport()->width() - 24);
    QTextDocument* doc = m_browser->document();
    for (QTextBlock block = doc->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            if (!image.isValid())
                continue;
            const QImage picture =
                doc->resource(QTextDocument::ImageResource, QUrl(image.name())).value<QImage>();
            // Never wider than the page, never wider than itself (a page made wider again
            // gives a shrunk image its room back); unchanged: left as it is.
            const double width = qMin(double(picture.width()), room);
            if (picture.isNull() || image.width() == width)
                continue;
            image.setWidth(width);
            image.setHeight(width * picture.height() / picture.width());
            QTextCursor cursor(doc);
            cursor.setPosition(fragment.position());
            cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(image);
        }
    }
}

} // namespace stepdeck::ui
