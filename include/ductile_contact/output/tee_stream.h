#pragma once

#include <fstream>
#include <ostream>
#include <streambuf>
#include <string>

namespace DuctileContact
{
  /**
   * An output stream that writes to the screen and, once open_file() has
   * been called, also to a file (results/log.txt: a copy of the screen).
   * Lines are flushed to the file as they come, so a run that fails keeps
   * its log.
   */
  class TeeStream : public std::ostream
  {
  public:
    explicit TeeStream(std::ostream &screen);

    /// @p append: continue the file (a resumed run) instead of replacing it.
    void
    open_file(const std::string &file_name, const bool append = false);

  private:
    class Buffer : public std::streambuf
    {
    public:
      Buffer(std::streambuf *a);
      std::streambuf *first;
      std::streambuf *second = nullptr;

    protected:
      int
      overflow(int c) override;
      std::streamsize
      xsputn(const char *s, std::streamsize n) override;
      int
      sync() override;
    };

    std::ofstream file;
    Buffer        buffer;
  };
} // namespace DuctileContact
