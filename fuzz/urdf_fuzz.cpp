// URDF bytes → read → every rule. Also checks the urdfdom skip: asset-lint must reject
// every document urdfdom rejects (src/formats/urdf/urdfdom_verdict.h); and the single parse:
// the XML scanner the reader builds its model from must reject every document tinyxml2 rejects.
#include <tinyxml2.h>

#include <cstdint>
#include <cstdlib>
#include <string>

#include "pipeline/lint.h"
#include "pipeline/urdf_verdict.h"
#include "formats/urdf/urdf_reader.h"
#include "formats/urdf/urdfdom_check.h"
#include "formats/xml/xml_scanner.h"
#include "memory_file_system.h"

using namespace assetlint;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fuzz::MemoryFileSystem files;
  (void)lint_text("fuzz.urdf", text, Settings{}, files);
  // The reader's own verdict (the report's may be changed by inline suppressions).
  const ReadResult read = urdf::read_urdf(std::make_shared<const SourceFile>("fuzz.urdf", text));
  if (!rejects_as_urdfdom_would(read) && !urdf::urdfdom_errors(text).empty()) std::abort();  // accepted what urdfdom rejects
  // A '<!' declaration other than a comment is the one place the two differ on purpose: the
  // scanner nests a DOCTYPE's internal subset as XML does, tinyxml2 ends it at the first '>'
  // (urdfdom runs on every document that has one).
  const xml::XmlScan scan = xml::scan_xml(text);
  if (scan.recoverable && !scan.tags.empty() && !scan.doctype_or_cdata) {
    const std::string_view document = std::string_view(text).substr(scan.document_begin, scan.document_end - scan.document_begin);
    tinyxml2::XMLDocument doc(true, tinyxml2::COLLAPSE_WHITESPACE);
    if (doc.Parse(document.data(), document.size()) != tinyxml2::XML_SUCCESS) std::abort();  // accepted what tinyxml2 rejects
  }
  return 0;
}
