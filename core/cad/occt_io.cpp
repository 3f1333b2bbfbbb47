#include "core/cad/occt_io.hpp"

#include <BRep_Builder.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESCAFControl_Writer.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESData_IGESEntity.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_ExtendedString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TransferBRep.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>

#include "core/base/data_error.hpp"
#include "core/io/atomic_file.hpp"

namespace pl {

namespace {

// An XDE document owned for the duration of a read or write.
class XdeDocument {
 public:
  XdeDocument() : app_(XCAFApp_Application::GetApplication()) {
    app_->NewDocument("MDTV-XCAF", doc_);
  }
  ~XdeDocument() { app_->Close(doc_); }
  XdeDocument(const XdeDocument&) = delete;
  XdeDocument& operator=(const XdeDocument&) = delete;
  Handle(TDocStd_Document) & doc() { return doc_; }
  Handle(XCAFDoc_ShapeTool) shapes() const { return XCAFDoc_DocumentTool::ShapeTool(doc_->Main()); }

 private:
  Handle(XCAFApp_Application) app_;
  Handle(TDocStd_Document) doc_;
};

std::string label_name(const TDF_Label& l) {
  Handle(TDataStd_Name) n;
  if (!l.FindAttribute(TDataStd_Name::GetID(), n)) return {};
  return TCollection_AsciiString(n->Get()).ToCString();
}

void set_name(const TDF_Label& l, const std::string& name) {
  TDataStd_Name::Set(l, TCollection_ExtendedString(name.c_str(), true));  // UTF-8
}

// IGES labels are right-justified in their 8-character field.
std::string trimmed(std::string s) {
  const auto first = s.find_first_not_of(' ');
  const auto last = s.find_last_not_of(' ');
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

std::mutex occt_mutex;  // OCCT's static parameters (Interface_Static) are process-wide

}  // namespace

void quiet_occt() {
  static std::once_flag once;
  std::call_once(once, [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  });
}

void write_cad_file(const SewnShape& shape, const CadModel& model, const std::string& product,
                    CadFormat format, const std::filesystem::path& target,
                    const std::vector<std::pair<std::string, TopoDS_Edge>>& curves,
                    const CadDeadline& deadline) {
  quiet_occt();
  const std::lock_guard<std::mutex> lock(occt_mutex);
  const CadPlace place{target.string(), ""};
  occt_call(place, "cannot write", [&] {
    XdeDocument xde;
    const Handle(XCAFDoc_ShapeTool) st = xde.shapes();
    TopoDS_Shape whole = shape.shape;
    if (!curves.empty()) {  // the surfaces and the curves in one compound
      BRep_Builder b;
      TopoDS_Compound c;
      b.MakeCompound(c);
      if (!shape.shape.IsNull()) b.Add(c, shape.shape);
      for (const auto& [name, edge] : curves) b.Add(c, edge);
      whole = c;
    }
    const TDF_Label root = st->AddShape(whole, Standard_False);
    set_name(root, product);
    for (std::size_t i = 0; i < shape.faces.size(); ++i) {
      if (shape.faces[i].IsNull()) continue;
      const TDF_Label l = st->AddSubShape(root, shape.faces[i]);
      if (!l.IsNull()) set_name(l, model.faces[i].name);
    }
    for (const auto& [name, edge] : curves) {
      const TDF_Label l = st->AddSubShape(root, edge);
      if (!l.IsNull()) set_name(l, name);
    }
    const std::string where = target.string();
    write_atomically_via(target, [&](const std::filesystem::path& tmp) {
      {  // OCCT reports a failed open without a reason: try it first to name the reason.
        std::ofstream probe(tmp, std::ios::binary | std::ios::trunc);
        if (!probe)
          throw DataError(where, "", std::string("cannot write: ") + std::strerror(errno));
      }
      IFSelect_ReturnStatus status = IFSelect_RetFail;
      errno = 0;  // OCCT's stream sets it when a write fails (ENOSPC on a full disk)
      if (format == CadFormat::Step) {
        STEPCAFControl_Controller::Init();
        // The schema must be set before the writer is constructed.
        Interface_Static::SetCVal("write.step.schema", "AP242DIS");
        Interface_Static::SetCVal("write.step.unit", "MM");
        Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);
        Interface_Static::SetCVal("write.step.product.name", product.c_str());
        STEPCAFControl_Writer writer;
        writer.SetNameMode(true);
        const Handle(Message_ProgressIndicator) progress = deadline.indicator();
        if (!occt_call_until(place, "translating the shape to STEP", deadline, [&] {
              return writer.Transfer(xde.doc(), STEPControl_AsIs, nullptr, progress->Start());
            }))
          throw DataError(where, "", "OpenCASCADE could not translate the shape to STEP");
        status = writer.Write(tmp.c_str());
      } else {
        IGESControl_Controller::Init();
        Interface_Static::SetIVal("write.iges.brep.mode", 1);  // faces keep their shells
        Interface_Static::SetCVal("write.iges.unit", "MM");
        IGESCAFControl_Writer writer;
        writer.SetNameMode(true);
        const Handle(Message_ProgressIndicator) progress = deadline.indicator();
        if (!occt_call_until(place, "translating the shape to IGES", deadline,
                             [&] { return writer.Transfer(xde.doc(), progress->Start()); }))
          throw DataError(where, "", "OpenCASCADE could not translate the shape to IGES");
        status = writer.Write(tmp.c_str()) ? IFSelect_RetDone : IFSelect_RetFail;
      }
      if (status != IFSelect_RetDone) {
        const int reason = errno;
        throw DataError(where, "",
                        std::string("writing failed: ") +
                            (reason ? std::strerror(reason) : "OpenCASCADE's writer gave up"));
      }
    });
  });
}

namespace {

CadFile read_cad_file_unguarded(const std::filesystem::path& path, CadFormat format,
                                const CadDeadline& deadline) {
  quiet_occt();
  const std::lock_guard<std::mutex> lock(occt_mutex);
  const std::string where = path.string();
  const CadPlace place{where, ""};
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw DataError(where, "", "no such file");
  XdeDocument xde;
  std::vector<std::pair<std::string, TopoDS_Shape>> iges_names;
  if (format == CadFormat::Step) {
    STEPCAFControl_Controller::Init();
    Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
    STEPCAFControl_Reader reader;
    reader.SetNameMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw DataError(where, "", "OpenCASCADE cannot read it as STEP");
    const Handle(Message_ProgressIndicator) progress = deadline.indicator();
    if (!occt_call_until(place, "translating the STEP file", deadline,
                         [&] { return reader.Transfer(xde.doc(), progress->Start()); }))
      throw DataError(where, "", "no shape in the STEP file");
  } else {
    IGESControl_Controller::Init();
    IGESCAFControl_Reader reader;
    reader.SetNameMode(true);
    if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
      throw DataError(where, "", "OpenCASCADE cannot read it as IGES");
    const Handle(Message_ProgressIndicator) progress = deadline.indicator();
    if (!occt_call_until(place, "translating the IGES file", deadline,
                         [&] { return reader.Transfer(xde.doc(), progress->Start()); }))
      throw DataError(where, "", "no shape in the IGES file");
    // The XDE reader names only top-level shapes; face names are the labels of the face
    // entities (IGES labels hold 8 characters), found through the transfer's results.
    const Handle(Interface_InterfaceModel) model = reader.WS()->Model();
    const Handle(Transfer_TransientProcess) tp = reader.WS()->TransferReader()->TransientProcess();
    for (int i = 1; i <= model->NbEntities(); ++i) {
      const auto e = Handle(IGESData_IGESEntity)::DownCast(model->Value(i));
      if (e.IsNull() || !e->HasShortLabel()) continue;
      const TopoDS_Shape s = TransferBRep::ShapeResult(tp, e);
      if (!s.IsNull() && s.ShapeType() == TopAbs_FACE)
        iges_names.emplace_back(trimmed(e->ShortLabel()->ToCString()), s);
    }
  }
  const Handle(XCAFDoc_ShapeTool) st = xde.shapes();
  TDF_LabelSequence roots;
  st->GetFreeShapes(roots);
  CadFile out;
  if (roots.Length() == 1) {
    out.shape = st->GetShape(roots(1));
    out.product = label_name(roots(1));
  } else {
    BRep_Builder b;
    TopoDS_Compound all;
    b.MakeCompound(all);
    for (int i = 1; i <= roots.Length(); ++i) b.Add(all, st->GetShape(roots(i)));
    out.shape = all;
  }
  // Names of sub-shape labels (faces), found again in the shape by identity.
  std::vector<std::pair<std::string, TopoDS_Shape>> named = iges_names;
  for (int i = 1; i <= roots.Length(); ++i) {
    TDF_LabelSequence subs;
    st->GetSubShapes(roots(i), subs);
    for (int k = 1; k <= subs.Length(); ++k)
      named.emplace_back(label_name(subs(k)), st->GetShape(subs(k)));
  }
  for (TopExp_Explorer e(out.shape, TopAbs_FACE); e.More(); e.Next()) {
    std::string name;
    for (const auto& [n, s] : named)
      if (s.IsSame(e.Current())) name = n;
    out.faces.emplace_back(name, TopoDS::Face(e.Current()));
  }
  // Edges: once each however many faces share one; a free curve is a root of its own.
  for (int i = 1; i <= roots.Length(); ++i)
    named.emplace_back(label_name(roots(i)), st->GetShape(roots(i)));
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(out.shape, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    std::string name;
    for (const auto& [n, s] : named)
      if (s.IsSame(edges(i))) name = n;
    out.edges.emplace_back(name, TopoDS::Edge(edges(i)));
  }
  return out;
}

}  // namespace

CadFile read_cad_file(const std::filesystem::path& path, CadFormat format,
                      const CadDeadline& deadline) {
  return occt_call({path.string(), ""}, "cannot read",
                   [&] { return read_cad_file_unguarded(path, format, deadline); });
}

}  // namespace pl
