// Zoltan's geometric partition of the particles: see ZoltanPartitioner.hpp.
#include "parallel/ZoltanPartitioner.hpp"
#include "parallel/Communicator.hpp"
#include <stdexcept>
#include <string>

#ifdef SHIZUKU_HAVE_MPI
#include <zoltan.h>
#endif

namespace shizuku {

#ifdef SHIZUKU_HAVE_MPI

// The objects Zoltan's query functions read: this rank's coordinates and ids.
struct ZoltanPartitioner::Impl {
  Zoltan_Struct* zz = nullptr;
  int dim = 2;
  const std::vector<double>* x = nullptr;
  const std::vector<std::int64_t>* ids = nullptr;

  static int count(void* data, int* ierr) {
    auto* self = static_cast<Impl*>(data);
    *ierr = ZOLTAN_OK;
    return int(self->ids->size());
  }
  // Global ids are the particles' 64-bit ids, two Zoltan id words each.
  static void list(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int, float*, int* ierr) {
    auto* self = static_cast<Impl*>(data);
    const auto& ids = *self->ids;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const auto u = std::uint64_t(ids[k]);
      gids[2 * k] = ZOLTAN_ID_TYPE(u & 0xffffffffu);
      gids[2 * k + 1] = ZOLTAN_ID_TYPE(u >> 32);
      lids[k] = ZOLTAN_ID_TYPE(k);
    }
    *ierr = ZOLTAN_OK;
  }
  static int dimension(void* data, int* ierr) {
    *ierr = ZOLTAN_OK;
    return static_cast<Impl*>(data)->dim;
  }
  static void coordinates(void* data, int, int, int n, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim, double* out,
                          int* ierr) {
    auto* self = static_cast<Impl*>(data);
    for (int k = 0; k < n; ++k)
      for (int a = 0; a < dim; ++a) out[k * dim + a] = (*self->x)[std::size_t(lids[k]) * dim + a];
    *ierr = ZOLTAN_OK;
  }
};

ZoltanPartitioner::ZoltanPartitioner(const std::string& method, int dim) : impl_(std::make_unique<Impl>()), method_(method) {
  if (!Communicator::world().started()) throw std::logic_error("ZoltanPartitioner: MPI is not started");
  static bool initialised = false;
  if (!initialised) {
    float version = 0;
    if (Zoltan_Initialize(0, nullptr, &version) != ZOLTAN_OK) throw std::runtime_error("Zoltan_Initialize failed");
    initialised = true;
  }
  impl_->dim = dim;
  impl_->zz = Zoltan_Create(MPI_COMM_WORLD);
  Zoltan_Struct* zz = impl_->zz;
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", method.c_str());
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "2");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", "0");   // every particle weighs one
  Zoltan_Set_Param(zz, "RETURN_LISTS", "EXPORT");
  Zoltan_Set_Param(zz, "KEEP_CUTS", "1");        // point assignment between partitions
  Zoltan_Set_Param(zz, "IMBALANCE_TOL", "1.02");
  // RCB_REUSE is set by each partition (below).
  Zoltan_Set_Num_Obj_Fn(zz, &Impl::count, impl_.get());
  Zoltan_Set_Obj_List_Fn(zz, &Impl::list, impl_.get());
  Zoltan_Set_Num_Geom_Fn(zz, &Impl::dimension, impl_.get());
  Zoltan_Set_Geom_Multi_Fn(zz, &Impl::coordinates, impl_.get());
}

ZoltanPartitioner::~ZoltanPartitioner() {
  if (impl_ && impl_->zz) Zoltan_Destroy(&impl_->zz);
}

void ZoltanPartitioner::partition(const std::vector<double>& x, const std::vector<std::int64_t>& ids, bool fromScratch,
                                  std::vector<int>& owner) {
  impl_->x = &x;
  impl_->ids = &ids;
  Zoltan_Set_Param(impl_->zz, "LB_APPROACH", fromScratch ? "PARTITION" : "REPARTITION");
  // A repartition starts from the last cuts; a partition from scratch from nothing, so that
  // it gives what a new partitioner gives on the same particles (a restart's).
  if (method_ == "RCB") Zoltan_Set_Param(impl_->zz, "RCB_REUSE", fromScratch ? "0" : "1");
  int changes = 0, numGid = 0, numLid = 0, numImport = 0, numExport = 0;
  ZOLTAN_ID_PTR importGids = nullptr, importLids = nullptr, exportGids = nullptr, exportLids = nullptr;
  int *importProcs = nullptr, *importParts = nullptr, *exportProcs = nullptr, *exportParts = nullptr;
  const int rc = Zoltan_LB_Partition(impl_->zz, &changes, &numGid, &numLid, &numImport, &importGids, &importLids,
                                     &importProcs, &importParts, &numExport, &exportGids, &exportLids, &exportProcs,
                                     &exportParts);
  if (rc != ZOLTAN_OK) throw std::runtime_error("Zoltan_LB_Partition failed with code " + std::to_string(rc));
  const int me = Communicator::world().rank();
  owner.assign(ids.size(), me);
  for (int k = 0; k < numExport; ++k) owner[exportLids[k]] = exportProcs[k];
  Zoltan_LB_Free_Part(&importGids, &importLids, &importProcs, &importParts);
  Zoltan_LB_Free_Part(&exportGids, &exportLids, &exportProcs, &exportParts);
  impl_->x = nullptr;
  impl_->ids = nullptr;
}

int ZoltanPartitioner::ownerOf(const double* x) const {
  int proc = -1, part = -1;
  Zoltan_LB_Point_PP_Assign(impl_->zz, const_cast<double*>(x), &proc, &part);
  return proc;
}

#else  // a serial build: one rank owns everything

struct ZoltanPartitioner::Impl {};
ZoltanPartitioner::ZoltanPartitioner(const std::string& method, int) : method_(method) {}
ZoltanPartitioner::~ZoltanPartitioner() = default;
void ZoltanPartitioner::partition(const std::vector<double>&, const std::vector<std::int64_t>& ids, bool,
                                  std::vector<int>& owner) {
  owner.assign(ids.size(), 0);
}
int ZoltanPartitioner::ownerOf(const double*) const { return 0; }

#endif

}  // namespace shizuku
