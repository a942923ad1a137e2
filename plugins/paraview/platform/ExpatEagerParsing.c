/* SPDX-License-Identifier: MIT */
/* Preloaded into ParaView (LD_PRELOAD) on systems whose expat defers parsing (expat 2.6, and
 * Debian 12's 2.5.0 with its security fixes): every XML parser VTK creates parses eagerly,
 * as VTK 9.2's XML readers expect. They feed expat a file's header in pieces and stop at
 * <AppendedData>; with deferral the tag is still pending when the binary block arrives, and
 * the reader fails ("not well-formed (invalid token)"). That breaks every piece ParaView
 * moves between MPI ranks (Redistribute DataSet, ordered compositing of volumes) and .vtu
 * files with appended arrays (docs/user/paraview.md). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <expat.h>

static XML_Parser eager(XML_Parser parser) {
  if (parser) XML_SetReparseDeferralEnabled(parser, XML_FALSE);
  return parser;
}

XML_Parser XML_ParserCreate(const XML_Char* encoding) {
  static XML_Parser (*create)(const XML_Char*);
  if (!create) create = (XML_Parser(*)(const XML_Char*))dlsym(RTLD_NEXT, "XML_ParserCreate");
  return create ? eager(create(encoding)) : NULL;
}

XML_Parser XML_ParserCreateNS(const XML_Char* encoding, XML_Char separator) {
  static XML_Parser (*create)(const XML_Char*, XML_Char);
  if (!create) create = (XML_Parser(*)(const XML_Char*, XML_Char))dlsym(RTLD_NEXT, "XML_ParserCreateNS");
  return create ? eager(create(encoding, separator)) : NULL;
}
