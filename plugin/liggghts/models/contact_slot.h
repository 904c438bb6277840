/* The in-memory hand-over between the sub-models of one contact model (a
   pair style's or a wall's). LIGGGHTS evaluates a contact's sub-models in a
   fixed order (surface, normal, cohesion, tangential, rolling; in
   collision() and in surfacesClose() alike), so a value that one computes
   and a later one reads in the same evaluation needs no contact history:
   the writer keeps it in a member and offers its address by name at
   set-up (postSettings, which runs in the same order); a reader finds it
   by contact model and name in its own postSettings. What must last to
   the next step stays in contact history. Data plumbing only. */
#ifndef DC_PLUGIN_CONTACT_SLOT_H
#define DC_PLUGIN_CONTACT_SLOT_H

#include <map>
#include <string>
#include <utility>

namespace LIGGGHTS {
namespace ContactModels {

class ContactModelBase;

class ContactSlots {
public:
  /* The writer's value, under name, for the sub-models of cmb. */
  static void offer(const ContactModelBase *cmb, const char *name, void *slot) { table()[Key(cmb, name)] = slot; }

  /* From the writer's destructor: a later contact model may take the address. */
  static void withdraw(const ContactModelBase *cmb, const char *name) { table().erase(Key(cmb, name)); }

  /* The value offered under name for cmb, or NULL. */
  template<class T>
  static T *find(const ContactModelBase *cmb, const char *name)
  {
    const Table::const_iterator it = table().find(Key(cmb, name));
    return it == table().end() ? static_cast<T *>(0) : static_cast<T *>(it->second);
  }

private:
  typedef std::pair<const ContactModelBase *, std::string> Key;
  typedef std::map<Key, void *> Table;
  static Table &table()
  {
    static Table t;
    return t;
  }
};

}
}
#endif
