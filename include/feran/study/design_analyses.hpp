#pragma once
/// @file
/// The analyses of one design, each run at most once, when a quantity first needs it,
/// with the settings of the design's own model tables, on one thread (studies run
/// designs side by side). The quantities' rows (study/quantity.hpp) read their values
/// off these results.

#include <map>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/core/error.hpp>
#include <feran/study/quantity.hpp>

namespace feran {

class DesignAnalyses {
 public:
  /// The quantities tell which probes and springs the response and the run-up record;
  /// they must outlive the object.
  DesignAnalyses(const ModelSpec& spec, const Model& model, std::span<const QuantitySpec> quantities, StopToken stop);
  ~DesignAnalyses() = default;
  DesignAnalyses(const DesignAnalyses&) = delete;
  DesignAnalyses& operator=(const DesignAnalyses&) = delete;

  const ModelSpec& spec() const { return spec_; }
  const Model& model() const { return model_; }
  const StopToken& stop() const { return stop_; }

  /// The options and result of analysis A for the design (its file's own table, and
  /// what A::study_request() asks for the quantities, if A has it), run once; throws
  /// Error when the solve failed.
  template <AnalysisFace A>
  const typename A::Options& options() {
    return slot<A>().options;
  }
  template <AnalysisFace A>
  const typename A::Result& result() {
    return slot<A>().result;
  }

 private:
  template <AnalysisFace A>
  struct Slot {
    typename A::Options options;
    typename A::Result result;
  };
  template <AnalysisFace A>
  const Slot<A>& slot() {
    std::shared_ptr<const void>& s = rooms_[A::name];
    if (!s) {
      auto made = std::make_shared<Slot<A>>();
      typename A::Spec request;
      if constexpr (requires { A::study_request(model_, quantities_); })
        request = A::study_request(model_, quantities_);
      made->options = analysis_options<A>(spec_, model_, request, file_key_name<A>());
      made->result = A::run(model_, made->options, RunContext{.stop = stop_});
      if (!made->result.info.converged())
        throw Error(fmt::format("the {} analysis failed: {}", A::name, made->result.info.message));
      s = std::move(made);
    }
    return *static_cast<const Slot<A>*>(s.get());
  }

  const ModelSpec& spec_;
  const Model& model_;
  StopToken stop_;
  std::span<const QuantitySpec> quantities_;
  std::map<std::string_view, std::shared_ptr<const void>> rooms_;
};

// What the rows' messages and selections share.
/// "1st", "2nd", "3rd", "4th", …
std::string ordinal(int n);
/// "forward ", "backward " or "" (any), before a noun.
std::string_view whirl_word(WhirlSelection s);
/// Whether a mode that whirls @p w is one a quantity selecting @p s looks at.
bool selected(Whirl w, WhirlSelection s);
/// The probes the quantities of analysis @p analysis name, each node once, as their
/// analysis's request takes them (study_request()).
std::vector<NodeRef> quantity_probes(const Model& model, std::span<const QuantitySpec> quantities,
                                     std::string_view analysis);
/// A speed as messages give it, in rpm.
std::string rpm(Real speed);

/// One bearing's state as a bearing-value quantity reads it: its label, the operating
/// quantities it has, and its values of the quantity's `value` at the points counted.
struct BearingValues {
  std::string label;
  std::vector<std::string> quantities;
  std::vector<Real> values;
};
/// The smallest (@p smallest) or largest finite value of @p q's `value` over the
/// bearings @p q selects (all, or the one named `bearing`), angles in rad. Throws Error
/// for a model without bearings, a bearing not named so, a quantity a bearing does not
/// have, or no value at all (@p where says where the analysis looked: " at the
/// equilibrium", " between 0 and 3000 rpm").
Real extreme_bearing_value(const QuantitySpec& q, bool smallest, const std::vector<BearingValues>& bearings,
                           const std::string& where);

}  // namespace feran
