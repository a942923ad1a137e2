// SPDX-License-Identifier: MIT
#include "ReaderOptionsDialog.hpp"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace volpost::app {

ReaderOptionsDialog::ReaderOptionsDialog(const MeshReader& reader, const QString& fileName,
                                         const ReaderOptions& current, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle("Reader options: " + fileName);
  auto* form = new QFormLayout(this);
  form->addRow(new QLabel(QString("%1, read by the %2 reader. Empty fields keep the defaults.")
                              .arg(fileName, QString::fromStdString(reader.formatName()))));
  for (const ReaderOption& o : reader.options()) {
    auto* edit = new QLineEdit(this);
    edit->setObjectName(QString::fromStdString("readerOption_" + o.name));
    edit->setToolTip(QString::fromStdString(o.description));
    edit->setPlaceholderText(QString::fromStdString(o.valueName));
    if (const auto it = current.find(o.name); it != current.end()) edit->setText(QString::fromStdString(it->second));
    form->addRow(QString::fromStdString(o.name), edit);
    fields_.emplace_back(o.name, edit);
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  buttons->button(QDialogButtonBox::Ok)->setText("Read Again");
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  form->addRow(buttons);
}

ReaderOptions ReaderOptionsDialog::chosen() const {
  ReaderOptions out;
  for (const auto& [name, edit] : fields_)
    if (const QString text = edit->text().trimmed(); !text.isEmpty()) out[name] = text.toStdString();
  return out;
}

}  // namespace volpost::app
