// Arrays: `array[N]`, `array[N][M]` (up to 5 dimensions), with an optional initializer
// `{ a, b, ... }` (nested braces per dimension), or `array { a, b }` sized by its list.
// Values are shared between copies until one is written (copy on write), so `#declare B = A`
// and passing an array to a macro copy nothing, and `#declare A[I] = ...` in a loop does not
// copy the array each time.
#include <string>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {
namespace {

constexpr std::size_t kMaxDimensions = 5;

std::string quoted_name(std::string_view name) {
  return name.empty() ? std::string("the array") : quoted(name);
}

}  // namespace

Value Parser::Impl::parse_array_declaration() {
  const TokenRef at = ref();
  advance();  // array
  // `array mixed[N]` (POV-Ray 3.7.1): elements of different types, as every array here may.
  if (plain().word == Word::mixed) advance();
  auto array = std::make_shared<Array>();
  std::size_t total = 1;
  while (plain_symbol('[')) {
    advance();
    const TokenRef size_at = ref();
    const int size = to_int(to_float(parse_expression(), size_at, "as an array size"), size_at,
                            "as an array size");
    if (size < 1) fail(size_at, "an array size must be at least 1, found " + std::to_string(size));
    if (array->dimensions.size() == kMaxDimensions) {
      fail(size_at, "an array has at most " + std::to_string(kMaxDimensions) + " dimensions");
    }
    total *= std::size_t(size);
    if (total > kMaxArrayElements) {
      fail(size_at,
           "array too large (more than " + std::to_string(kMaxArrayElements) + " elements)");
    }
    array->dimensions.push_back(size);
    expect_symbol(']', "after the array size");
  }
  if (array->dimensions.empty()) {
    // `array { a, b, c }`: one dimension, as long as the list.
    if (!plain_symbol('{')) fail_here("expected '[' with the array's size after 'array'");
    advance();
    while (!accept_symbol('}')) {
      if (array->elements.size() == kMaxArrayElements) fail_here("array too large");
      const TokenRef element_at = ref();
      Value element = parse_rvalue();
      recount_elements(array->counted, array->counted.count() + 1 + string_elements(element),
                       loc(element_at));
      array->elements.push_back(std::move(element));
      accept_symbol(',');  // optional, as POV-Ray's commas are
    }
    if (array->elements.empty()) fail(at, "an array needs at least one element");
    array->dimensions.push_back(int(array->elements.size()));
    return Value{array, {}};
  }
  charge(total / kElementsPerToken);
  array->counted = reserve_elements(total, at);
  array->elements.resize(total);
  if (plain_symbol('{')) {
    std::size_t next = 0;
    parse_array_initializer(*array, 0, next);
  }
  return Value{array, {}};
}

void Parser::Impl::parse_array_initializer(Array& array, std::size_t dimension, std::size_t& next) {
  expect_symbol('{', "to start the elements of array dimension " + std::to_string(dimension + 1));
  std::size_t stride = 1;
  for (std::size_t d = dimension + 1; d < array.dimensions.size(); ++d) {
    stride *= std::size_t(array.dimensions[d]);
  }
  const std::size_t base = next;
  const int size = array.dimensions[dimension];
  int count = 0;
  while (!accept_symbol('}')) {
    if (count == size) {
      fail_here("too many elements: array dimension " + std::to_string(dimension + 1) + " has " +
                std::to_string(size));
    }
    if (dimension + 1 < array.dimensions.size()) {
      parse_array_initializer(array, dimension + 1, next);
    } else {
      const TokenRef element_at = ref();
      Value element = parse_rvalue();
      recount_elements(array.counted, array.counted.count() + string_elements(element),
                       loc(element_at));
      array.elements[next++] = std::move(element);
    }
    ++count;
    accept_symbol(',');  // optional, as POV-Ray's commas are
  }
  next = base + std::size_t(size) * stride;
}

std::size_t Parser::Impl::parse_index_group(const Array& array, std::string_view name) {
  std::size_t flat = 0;
  for (std::size_t d = 0; d < array.dimensions.size(); ++d) {
    if (!plain_symbol('[')) {
      fail_here(quoted_name(name) + " has " + std::to_string(array.dimensions.size()) +
                " dimensions: expected '[' for index " + std::to_string(d + 1) + ", found " +
                describe(plain()));
    }
    advance();
    const TokenRef at = ref();
    const double value = to_float(parse_expression(), at, "as an array index");
    expect_symbol(']', "after the array index");
    const int size = array.dimensions[d];
    const double index = std::trunc(value);
    if (!(index >= 0.0 && index < double(size))) {
      fail(at, "array index " + number_text(index) + " out of range: " + quoted_name(name) +
                   " has " + std::to_string(size) + " elements there (0 to " +
                   std::to_string(size - 1) + ")");
    }
    flat = flat * std::size_t(size) + std::size_t(index);
  }
  return flat;
}

Value Parser::Impl::index_array(const Value& array_value, TokenRef at, std::string_view name) {
  const std::shared_ptr<Array> array = *array_value.get<std::shared_ptr<Array>>();
  const std::size_t flat = parse_index_group(*array, name);
  const Value& element = array->elements[flat];
  if (!element.is_set()) {
    fail(at, "an element of " + quoted_name(name) + " is read before it was given a value");
  }
  return element;
}

std::vector<std::size_t> Parser::Impl::parse_element_path(const Value& root,
                                                          std::string_view name) {
  // One flat index per array level: A[i][j] of a 2-D array is one level; A[i][j] of an array
  // of arrays is two.
  std::vector<std::size_t> path;
  Value level = root;
  for (;;) {
    const auto* array = level.get<std::shared_ptr<Array>>();
    if (array == nullptr) fail_here(quoted_name(name) + " is not an array");
    const std::shared_ptr<Array> held = *array;
    path.push_back(parse_index_group(*held, name));
    if (!plain_symbol('[')) return path;
    level = held->elements[path.back()];
  }
}

Value* Parser::Impl::element_at(Value& root, const std::vector<std::size_t>& path, bool for_write,
                                std::string_view name, TokenRef at) {
  Value* cursor = &root;
  for (const std::size_t flat : path) {
    auto* array = std::get_if<std::shared_ptr<Array>>(&cursor->data);
    if (array == nullptr || *array == nullptr || flat >= (*array)->elements.size()) {
      fail(at, quoted_name(name) + " changed while its index was computed");
    }
    if (for_write && array->use_count() > 1) {
      charge((*array)->elements.size() / kElementsPerToken);
      reserve_elements((*array)->counted.count(), at);  // the copy holds them again
      *array = std::make_shared<Array>(**array);
    }
    cursor = &(*array)->elements[flat];
  }
  return cursor;
}

void Parser::Impl::store_element(Value& root, const std::vector<std::size_t>& path, Value value,
                                 std::string_view name, TokenRef at) {
  Value* slot = element_at(root, path, true, name, at);
  // The array that holds the slot, now unshared: the last level of the path.
  Value* holder = &root;
  for (std::size_t level = 0; level + 1 < path.size(); ++level) {
    holder = &std::get<std::shared_ptr<Array>>(holder->data)->elements[path[level]];
  }
  Array& array = **std::get_if<std::shared_ptr<Array>>(&holder->data);
  recount_elements(array.counted,
                   array.counted.count() - string_elements(*slot) + string_elements(value),
                   loc(at));
  *slot = std::move(value);
}

std::size_t Parser::Impl::string_elements(const Value& value) {
  const auto* text = value.get<std::string>();
  return text ? text->size() / kStringBytesPerElement : 0;
}

void Parser::Impl::check_element_budget(std::size_t more, const SourceLoc& at) const {
  const std::size_t budget = options.max_live_array_elements;
  if (more > budget - std::min<std::size_t>(live_array_elements->load(), budget)) {
    fail(at, "the scene's arrays, strings and meshes would hold more than " +
                 std::to_string(budget) +
                 " elements in all (an array of arrays counts every element of each, a string "
                 "in an array one more per " +
                 std::to_string(kStringBytesPerElement) +
                 " characters, a mesh one per vertex, normal, texture and face)");
  }
}

ElementCount Parser::Impl::reserve_elements(std::size_t count, TokenRef at) {
  check_element_budget(count, loc(at));
  return ElementCount(live_array_elements, count);
}

void Parser::Impl::recount_elements(ElementCount& held, std::size_t count, const SourceLoc& at) {
  if (count > held.count()) check_element_budget(count - held.count(), at);
  held = ElementCount(live_array_elements, count);
}

}  // namespace convray::sdl
