// Copyright (c) 2026 Delaunay_from_prediction contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Delaunay_from_prediction founding team
//
// Reading and writing the text files of file_io.h: a reader that hands out one line at a time
// from a fixed buffer (memory does not grow with the file), the numbers of a line parsed by
// std::from_chars, and a buffered writer formatting with std::to_chars (the shortest text that
// reads back to the same double). Every error names the file and the line.

#ifndef CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IO_TEXT_FILE_H
#define CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IO_TEXT_FILE_H

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Delaunay_from_prediction {
namespace IO {

/*!
\ingroup PkgDelaunayFromPredictionRef
Exception thrown by the functions of `file_io.h` for a file that cannot be opened, read or
written, or whose content is malformed. `what()` is `file:line: message`, or `file: message`
when no line is concerned (`line()` is then 0). Lines are numbered from 1, comments and blank
lines included, as an editor numbers them.
*/
class File_error : public std::runtime_error
{
public:
  /// constructs the exception for line `line` (0: the whole file) of `file`.
  File_error(const std::string& file, std::size_t line, const std::string& message)
      : std::runtime_error(file + (line == 0 ? std::string() : ":" + std::to_string(line)) + ": " + message),
        file_(file), line_(line)
  {}
  /// the name of the file, as it was given.
  const std::string& file() const { return file_; }
  /// the line (from 1), or 0 when the error is not about one line.
  std::size_t line() const { return line_; }

private:
  std::string file_;
  std::size_t line_;
};

} // namespace IO

namespace internal {

struct File_closer
{
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File_handle = std::unique_ptr<std::FILE, File_closer>;

// Blanks between fields; commas count as blanks ("x, y" lines are common). A plain test:
// string_view::find_first_of would call memchr once per character.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\f' || c == '\v'; }

inline bool is_blank_line(std::string_view line)
{
  for(char c : line)
    if(!is_blank(c))
      return false;
  return true;
}

// One line at a time, without its end of line (\n or \r\n) and without what follows a `#`
// (a comment, in every format read here). The buffer holds at least one whole line: it grows
// only for a line longer than it, so memory is that of the longest line, not of the file.
class Line_reader
{
public:
  explicit Line_reader(const std::string& file) : file_(file), buffer_(1 << 20)
  {
    handle_.reset(std::fopen(file.c_str(), "rb"));
    if(!handle_)
      throw IO::File_error(file, 0, std::string("cannot open the file for reading (") + std::strerror(errno) + ")");
  }

  // The next line; false at the end of the file.
  bool next(std::string_view& line)
  {
    for(;;) {
      const char* begin = buffer_.data() + start_;
      const char* end = buffer_.data() + filled_;
      const char* newline = static_cast<const char*>(std::memchr(begin, '\n', std::size_t(end - begin)));
      if(newline != nullptr || (at_end_ && begin != end)) {
        const char* line_end = newline != nullptr ? newline : end;
        start_ = std::size_t((newline != nullptr ? newline + 1 : end) - buffer_.data());
        ++line_number_;
        line = std::string_view(begin, std::size_t(line_end - begin));
        if(!line.empty() && line.back() == '\r')
          line.remove_suffix(1);
        const std::size_t hash = line.find('#');
        if(hash != std::string_view::npos)
          line = line.substr(0, hash);
        return true;
      }
      if(at_end_)
        return false;
      refill();
    }
  }

  // The next line with something other than blanks on it; false at the end of the file.
  bool next_nonblank(std::string_view& line)
  {
    while(next(line))
      if(!is_blank_line(line))
        return true;
    return false;
  }

  std::size_t line_number() const { return line_number_; }
  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& message) const { throw IO::File_error(file_, line_number_, message); }

private:
  void refill()
  {
    // Keep the unfinished line, at the front; grow the buffer when it fills it.
    const std::size_t kept = filled_ - start_;
    std::memmove(buffer_.data(), buffer_.data() + start_, kept);
    start_ = 0;
    filled_ = kept;
    if(filled_ == buffer_.size())
      buffer_.resize(2 * buffer_.size());
    const std::size_t got = std::fread(buffer_.data() + filled_, 1, buffer_.size() - filled_, handle_.get());
    filled_ += got;
    if(got == 0) {
      if(std::ferror(handle_.get()))
        throw IO::File_error(file_, line_number_ + 1, "read error");
      at_end_ = true;
    }
  }

  std::string file_;
  File_handle handle_;
  std::vector<char> buffer_;
  std::size_t start_ = 0, filled_ = 0, line_number_ = 0;
  bool at_end_ = false;
};

// The blank-separated fields of a line.
class Fields
{
public:
  Fields(std::string_view line, const Line_reader& reader) : rest_(line), reader_(&reader) {}

  // The next field; false when none is left.
  bool next(std::string_view& field)
  {
    const char* p = rest_.data();
    const char* end = p + rest_.size();
    while(p != end && is_blank(*p))
      ++p;
    if(p == end) {
      rest_ = std::string_view();
      return false;
    }
    const char* last = p;
    while(last != end && !is_blank(*last))
      ++last;
    field = std::string_view(p, std::size_t(last - p));
    rest_ = std::string_view(last, std::size_t(end - last));
    return true;
  }

  std::size_t remaining()
  {
    Fields copy = *this;
    std::size_t count = 0;
    std::string_view field;
    while(copy.next(field))
      ++count;
    return count;
  }

  // A finite double; `what` names it in the error message.
  double real(const char* what)
  {
    std::string_view field;
    if(!next(field))
      reader_->fail(std::string("expected ") + what + ", found the end of the line");
    std::string_view digits = field;
    if(!digits.empty() && digits.front() == '+')
      digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if(error == std::errc::result_out_of_range)
      reader_->fail(std::string(what) + " '" + std::string(field) + "' is not representable as a double");
    if(error != std::errc() || end != digits.data() + digits.size())
      reader_->fail(std::string("expected ") + what + ", found '" + std::string(field) + "'");
    if(!std::isfinite(value))
      reader_->fail(std::string(what) + " '" + std::string(field) + "' is not finite");
    return value;
  }

  // A non-negative integer; `what` names it in the error message.
  std::uint64_t count(const char* what)
  {
    std::string_view field;
    if(!next(field))
      reader_->fail(std::string("expected ") + what + ", found the end of the line");
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if(error != std::errc() || end != field.data() + field.size()) {
      if(!field.empty() && field.front() == '-')
        reader_->fail(std::string(what) + " '" + std::string(field) + "' is negative");
      reader_->fail(std::string("expected ") + what + " (a non-negative integer), found '" + std::string(field) + "'");
    }
    return value;
  }

private:
  std::string_view rest_;
  const Line_reader* reader_;
};

// Buffered output to a file; every number is written with std::to_chars. `close()` reports a
// failed write (a full disk, say) as an error naming the file.
class Text_writer
{
public:
  explicit Text_writer(const std::string& file) : file_(file)
  {
    handle_.reset(std::fopen(file.c_str(), "wb"));
    if(!handle_)
      throw IO::File_error(file, 0, std::string("cannot open the file for writing (") + std::strerror(errno) + ")");
    buffer_.reserve(capacity);
  }

  Text_writer& text(std::string_view s)
  {
    reserve(s.size());
    buffer_.insert(buffer_.end(), s.begin(), s.end());
    return *this;
  }

  template <class Number>
  Text_writer& number(Number value)
  {
    reserve(32);
    char digits[32];
    const auto result = std::to_chars(digits, digits + sizeof digits, value);
    buffer_.insert(buffer_.end(), digits, result.ptr);
    return *this;
  }

  void close()
  {
    flush();
    std::FILE* f = handle_.release();
    if(std::fclose(f) != 0 || failed_)
      throw IO::File_error(file_, 0, "could not write the file");
  }

private:
  static constexpr std::size_t capacity = 1 << 20;

  void reserve(std::size_t more)
  {
    if(buffer_.size() + more > capacity)
      flush();
  }

  void flush()
  {
    if(!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), handle_.get()) != buffer_.size())
      failed_ = true;
    buffer_.clear();
  }

  std::string file_;
  File_handle handle_;
  std::vector<char> buffer_;
  bool failed_ = false;
};

} // namespace internal
} // namespace Delaunay_from_prediction
} // namespace CGAL

#endif // CGAL_DELAUNAY_FROM_PREDICTION_INTERNAL_IO_TEXT_FILE_H
