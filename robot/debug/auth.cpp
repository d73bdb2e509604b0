#include "robot/debug/auth.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>

#include "robot/core/error.hpp"
#include "robot/debug/protocol.hpp"

namespace stride::debug {

namespace {

constexpr std::size_t kMinToken = 16;

Token parse_token_line(const std::string& path, int number, std::string line) {
  Token t;
  if (line.starts_with("read-only ")) {
    t.read_only = true;
    line.erase(0, 10);
  }
  if (line.find_first_of(" \t") != std::string::npos)
    throw error_at(path, number,
                   "expected '<token>' or 'read-only <token>' (no spaces in a token)");
  if (line.size() < kMinToken)
    throw error_at(path, number, "token shorter than " + std::to_string(kMinToken) + " characters");
  t.secret = line;
  return t;
}

}  // namespace

std::vector<Token> read_token_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw Error("token file '" + path + "' does not exist");
  if (!S_ISREG(st.st_mode)) throw Error("token file '" + path + "' is not a regular file");
  if (st.st_mode & (S_IRWXG | S_IRWXO))
    throw Error("token file '" + path + "' may be read by others (chmod 600 it)");
  std::ifstream in(path);
  if (!in) throw Error("cannot read token file '" + path + "'");
  std::vector<Token> tokens;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    tokens.push_back(parse_token_line(path, number, line));
  }
  if (tokens.empty()) throw Error("token file '" + path + "' holds no token");
  return tokens;
}

std::vector<Token> tokens_from(const std::string& file) {
  if (!file.empty()) return read_token_file(file);
  const char* env = std::getenv("STRIDE_TOKEN");
  if (!env || !*env) return {};
  return {parse_token_line("STRIDE_TOKEN", 1, env)};
}

std::string random_nonce() {
  std::string nonce(kNonceBytes, '\0');
  if (RAND_bytes(reinterpret_cast<unsigned char*>(nonce.data()), static_cast<int>(kNonceBytes)) !=
      1)
    throw Error("no random bytes for the nonce (OpenSSL RAND_bytes)");
  return nonce;
}

std::string keyed_hash(std::string_view key, std::string_view message) {
  unsigned char out[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  if (!HMAC(EVP_sha256(), key.data(), static_cast<int>(key.size()),
            reinterpret_cast<const unsigned char*>(message.data()), message.size(), out, &n))
    throw Error("HMAC-SHA256 failed (OpenSSL)");
  return std::string(reinterpret_cast<const char*>(out), n);
}

std::string client_proof(std::string_view token, std::string_view server_nonce,
                         std::string_view client_nonce) {
  return keyed_hash(
      token, "stride-debug-1 client" + std::string(server_nonce) + std::string(client_nonce));
}

std::string server_proof(std::string_view token, std::string_view server_nonce,
                         std::string_view client_nonce) {
  return keyed_hash(
      token, "stride-debug-1 server" + std::string(server_nonce) + std::string(client_nonce));
}

bool same_proof(std::string_view a, std::string_view b) {
  return a.size() == b.size() && CRYPTO_memcmp(a.data(), b.data(), a.size()) == 0;
}

}  // namespace stride::debug
