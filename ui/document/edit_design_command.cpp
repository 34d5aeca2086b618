#include "ui/document/edit_design_command.h"

#include "ui/document/mechanism_document.h"

namespace linkwright::ui {

EditDesignCommand::EditDesignCommand(MechanismDocument* document, DesignState before, DesignState after,
                                     const QString& text, std::optional<MergeKey> mergeKey, bool another)
    : QUndoCommand(text), m_document(document), m_before(std::move(before)), m_after(std::move(after)),
      m_mergeKey(mergeKey), m_another(another) {}

void EditDesignCommand::undo() { m_document->applyDesign(m_before, m_another); }

void EditDesignCommand::redo() { m_document->applyDesign(m_after, m_another); }

bool EditDesignCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const EditDesignCommand*>(other);
  if (next == nullptr || !m_mergeKey || next->m_mergeKey != m_mergeKey) return false;
  m_after = next->m_after;
  return true;
}

}  // namespace linkwright::ui
