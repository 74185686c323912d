#pragma once
#include <QDialog>
#include <QList>
#include <QUrl>

class QListWidget;
class QTextBrowser;

namespace stepdeck::ui {

// Help > Documentation (issue 31: the Help menu had no documentation): the README (quick start,
// the workspaces), docs/machines.md, docs/programs.md and docs/cli.md, embedded in the program
// (resource prefix /docs) so that an installed StepDeck has them without the source tree. A
// list of the documents beside a browser; links between them and their images resolve inside
// the resources. The documents are in English (the manuals of the project are).
class DocumentationDialog : public QDialog
{
    Q_OBJECT
public:
    struct Document
    {
        QString title;
        QUrl source; // qrc:/docs/...
    };
    static QList<Document> documents();

    explicit DocumentationDialog(QWidget* parent = nullptr);
    void showDocument(int document); // its index in documents()
    QTextBrowser* browser() const { return m_browser; }
    QListWidget* list() const { return m_list; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override; // images follow the page width

private:
    void fitImages();

    QListWidget* m_list;
    QTextBrowser* m_browser;
};

} // namespace stepdeck::ui
