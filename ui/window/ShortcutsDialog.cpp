// Help > Keyboard shortcuts (ShortcutsDialog.h).
#include "ShortcutsDialog.h"
#include <QAction>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace stepdeck::ui {

QList<QPair<QString, QString>> ShortcutsDialog::rows(QWidget* window, const QString& jogKeys)
{
    QList<QPair<QString, QString>> safety, others;
    QStringList seen;
    for (const QAction* a : window->findChildren<QAction*>()) {
        if (a->shortcut().isEmpty())
            continue;
        const QString key = a->shortcut().toString(QKeySequence::NativeText);
        QString text = a->text();
        text.remove(QLatin1Char('&'));
        if (text.isEmpty() || seen.contains(key))
            continue;
        seen << key;
        // Application-wide shortcuts are the safety keys: they work wherever the focus is.
        (a->shortcutContext() == Qt::ApplicationShortcut ? safety : others) << qMakePair(key, text);
    }
    if (!jogKeys.isEmpty())
        others << qMakePair(jogKeys, tr("Keyboard jog, while it is on: hold the key to move"));
    return safety + others;
}

ShortcutsDialog::ShortcutsDialog(QWidget* window, const QString& jogKeys, QWidget* parent)
    : QDialog(parent), m_table(new QTableWidget(this))
{
    setWindowTitle(tr("Keyboard shortcuts"));
    const QList<QPair<QString, QString>> list = rows(window, jogKeys);
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setColumnCount(2);
    m_table->setHorizontalHeaderLabels({tr("Key"), tr("Action")});
    m_table->setRowCount(int(list.size()));
    for (int r = 0; r < list.size(); ++r) {
        m_table->setItem(r, 0, new QTableWidgetItem(list.at(r).first));
        m_table->setItem(r, 1, new QTableWidgetItem(list.at(r).second));
    }
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(560, 420);
}

} // namespace stepdeck::ui
