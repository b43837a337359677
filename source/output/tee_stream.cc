#include <ductile_contact/output/tee_stream.h>

namespace DuctileContact
{
  TeeStream::Buffer::Buffer(std::streambuf *a)
      : first(a)
  {
  }



  int
  TeeStream::Buffer::overflow(const int c)
  {
    if (c == EOF)
      return !EOF;
    const int r1 = first->sputc(static_cast<char>(c));
    const int r2 = second ? second->sputc(static_cast<char>(c)) : c;
    return (r1 == EOF || r2 == EOF) ? EOF : c;
  }



  std::streamsize
  TeeStream::Buffer::xsputn(const char *s, const std::streamsize n)
  {
    const std::streamsize n1 = first->sputn(s, n);
    if (second)
      second->sputn(s, n);
    return n1;
  }



  int
  TeeStream::Buffer::sync()
  {
    const int r1 = first->pubsync();
    const int r2 = second ? second->pubsync() : 0;
    return (r1 == 0 && r2 == 0) ? 0 : -1;
  }



  TeeStream::TeeStream(std::ostream &screen)
      : std::ostream(nullptr)
      , buffer(screen.rdbuf())
  {
    rdbuf(&buffer);
  }



  void
  TeeStream::open_file(const std::string &file_name, const bool append)
  {
    file.open(file_name, append ? std::ios::app : std::ios::out);
    buffer.second = file.rdbuf();
  }
} // namespace DuctileContact
