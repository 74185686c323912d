#include "Registry.h"
#include "model/NearestName.h"
#include "protocols/elab/ElabModel.h"
#include "protocols/emis/EmisModel.h"
#include "protocols/laser/LaserModel.h"
#include "protocols/nanotec/NanotecModel.h"
#include <QCoreApplication>

namespace stepdeck {

const QList<ModelInfo>& models()
{
    // The one explicit list of models.
    static const QList<ModelInfo> list{
        elab::modelInfo(),
        nanotec::modelInfo(),
        emis::modelInfo(),
        laser::modelInfo(),
    };
    return list;
}

const ModelInfo* findModel(const QString& id)
{
    for (const ModelInfo& model : models()) {
        if (model.id == id)
            return &model;
    }
    return nullptr;
}

QStringList modelIds()
{
    QStringList ids;
    for (const ModelInfo& model : models())
        ids << model.id;
    return ids;
}

QString unknownModelText(const QString& id)
{
    const QString known = modelIds().join(QStringLiteral(", "));
    const QString close = names::nearest(id, modelIds());
    if (close.isEmpty())
        return QCoreApplication::translate("stepdeck::ControllerSession",
                                           "unknown controller model '%1' (known: %2)")
            .arg(id, known);
    return QCoreApplication::translate("stepdeck::ControllerSession",
                                       "unknown controller model '%1' (did you mean %2? known: %3)")
        .arg(id, close, known);
}

} // namespace stepdeck
