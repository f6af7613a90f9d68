#include "brb/validation/contrast.hpp"

#include "brb/io/json_input.hpp"
#include "brb/validation/metric_kinds.hpp"

#include <algorithm>
#include <set>

namespace brb::validation {
namespace {

using io::JsonValue;

constexpr std::size_t kMostContrasts = 1000;

ContrastSpec::Operand read_operand(const JsonValue& value, const std::vector<Specimen>& specimens) {
  value.expect_object({"specimen", "metric"}, "{\"specimen\": id, \"metric\": name}");
  const JsonValue specimen_value = value.at("specimen", "a specimen's id (its folder's name)");
  const JsonValue metric_value = value.at("metric", "the name of one of that specimen's metrics");
  ContrastSpec::Operand operand{specimen_value.string("specimen id"),
                                metric_value.string("metric name")};
  const auto specimen = std::find_if(specimens.begin(), specimens.end(),
                                     [&](const Specimen& s) { return s.id == operand.specimen; });
  if (specimen == specimens.end())
    throw specimen_value.error("no specimen \"" + operand.specimen + "\" in the validation folder");
  const auto metric = std::find_if(specimen->metrics.begin(), specimen->metrics.end(),
                                   [&](const MetricSpec& m) { return m.name == operand.metric; });
  if (metric == specimen->metrics.end()) {
    throw metric_value.error("specimen \"" + operand.specimen + "\" has no metric \"" +
                             operand.metric + "\" (" + specimen->metrics_file.string() + ")");
  }
  if (find_metric_kind(metric->kind)->is_flag)
    throw metric_value.error("a flag cannot be compared; name a numeric metric");
  return operand;
}

std::optional<double> value_of(const RunOutcome& run, const std::string& metric) {
  for (const CheckResult& check : run.checks) {
    if (check.name == metric)
      return check.value;
  }
  return std::nullopt;
}

const SpecimenOutcome* outcome_of(const std::vector<SpecimenOutcome>& outcomes,
                                  const std::string& id) {
  for (const SpecimenOutcome& outcome : outcomes) {
    if (outcome.specimen.id == id)
      return &outcome;
  }
  return nullptr;
}

} // namespace

std::vector<ContrastSpec> read_contrasts(const std::filesystem::path& file,
                                         const std::vector<Specimen>& specimens) {
  const nlohmann::json document = io::read_json_file(file);
  const JsonValue root(document, file.string());
  root.expect_object({"contrasts"}, "an object {\"contrasts\": [...]}");
  const JsonValue list = root.at("contrasts", "the list of contrasts");
  const std::size_t count = list.expect_array(kMostContrasts, "a list of contrast objects");
  std::vector<ContrastSpec> contrasts;
  std::set<std::string> names;
  for (std::size_t i = 0; i < count; ++i) {
    const JsonValue value = list.element(i);
    value.expect_object({"name", "statement", "source", "left", "relation", "right"},
                        "a contrast {\"name\", \"statement\", \"source\", \"left\", "
                        "\"relation\", \"right\"}");
    ContrastSpec contrast;
    const JsonValue name = value.at("name", "the contrast's name, unique in the file");
    contrast.name = name.string("name");
    if (!names.insert(contrast.name).second)
      throw name.error("contrast \"" + contrast.name + "\" is defined twice");
    contrast.statement = value.at("statement", "the claim in words").string("statement");
    contrast.source = value.at("source", "where the claim comes from").string("source");
    contrast.left = read_operand(value.at("left", "the left operand"), specimens);
    const JsonValue relation = value.at("relation", "\">\" or \"<\"");
    contrast.relation = relation.string("relation");
    if (contrast.relation != ">" && contrast.relation != "<")
      throw relation.error("relation must be \">\" or \"<\" (got \"" + contrast.relation + "\")");
    contrast.right = read_operand(value.at("right", "the right operand"), specimens);
    contrasts.push_back(std::move(contrast));
  }
  return contrasts;
}

std::vector<ContrastResult> evaluate_contrasts(const std::vector<ContrastSpec>& contrasts,
                                               const std::vector<SpecimenOutcome>& outcomes) {
  std::vector<ContrastResult> results;
  for (const ContrastSpec& contrast : contrasts) {
    const SpecimenOutcome* left = outcome_of(outcomes, contrast.left.specimen);
    const SpecimenOutcome* right = outcome_of(outcomes, contrast.right.specimen);
    bool shared_run = false;
    if (left != nullptr && right != nullptr) {
      for (const RunOutcome& left_run : left->runs) {
        for (const RunOutcome& right_run : right->runs) {
          if (left_run.refinement != right_run.refinement)
            continue;
          shared_run = true;
          ContrastResult result{contrast,
                                left_run.refinement,
                                value_of(left_run, contrast.left.metric),
                                value_of(right_run, contrast.right.metric),
                                CheckStatus::fail,
                                ""};
          if (result.left && result.right) {
            const bool holds = contrast.relation == ">" ? *result.left > *result.right
                                                        : *result.left < *result.right;
            result.status = holds ? CheckStatus::pass : CheckStatus::fail;
          } else {
            result.note = "a metric has no value";
          }
          results.push_back(std::move(result));
        }
      }
    }
    if (!shared_run) {
      results.push_back(ContrastResult{contrast, std::nullopt, std::nullopt, std::nullopt,
                                       CheckStatus::reported,
                                       "not checked: the two specimens did not run at a common "
                                       "refinement in this invocation"});
    }
  }
  return results;
}

} // namespace brb::validation
