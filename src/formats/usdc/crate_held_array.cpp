#include "formats/usdc/crate_held_array.h"

#include <string>
#include <utility>

#include "formats/usdc/crate_types.h"
#include "formats/usdc/crate_value_nodes.h"

namespace assetlint::usdc {
namespace {

class HeldArray final : public usda::HeldItems {
 public:
  HeldArray(ArrayItems items, Span span) : element_(*items.element), count_(items.count), span_(span) {
    bytes_ = items.storage.empty() ? std::string(items.raw) : std::move(items.storage);
  }

  void append_numbers(std::vector<double>& out) const override {
    const std::size_t size = size_of(element_.num);
    const auto components = static_cast<std::size_t>(element_.components);
    out.reserve(out.size() + count_ * components);
    for (std::size_t i = 0; i < count_; ++i) {
      const char* p = bytes_.data() + i * components * size;
      for (std::size_t k = 0; k < components; ++k) {
        // Crate stores a quaternion x, y, z, w; USDA writes w first.
        const std::size_t stored = element_.quat ? (k + 3) % 4 : k;
        out.push_back(read_as_text(element_.num, p + stored * size).number);
      }
    }
  }

  std::vector<usda::Value> elements() const override {
    const std::size_t element_bytes = size_of(element_.num) * static_cast<std::size_t>(element_.components);
    const std::function<Span()> mark = [this] { return span_; };
    NumberCache numbers;
    std::vector<usda::Value> out(count_);
    for (std::size_t i = 0; i < count_; ++i)
      number_element_node(out[i], element_, bytes_.data() + i * element_bytes, mark, numbers);
    return out;
  }

 private:
  Element element_;
  std::size_t count_;
  Span span_;
  std::string bytes_;
};

}  // namespace

std::shared_ptr<const usda::HeldItems> hold_numeric_array(ArrayItems items, Span span) {
  return std::make_shared<const HeldArray>(std::move(items), span);
}

}  // namespace assetlint::usdc
