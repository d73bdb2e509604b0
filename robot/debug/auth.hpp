#pragma once
// Challenge-response with a shared token (HMAC-SHA256 from OpenSSL's libcrypto): the server sends
// a random nonce, the client answers with a keyed hash of it and a nonce of its own, the server
// answers that one. The token never crosses the wire, and each side proves it knows it.
#include <string>
#include <string_view>
#include <vector>

namespace stride::debug {

struct Token {
  std::string secret;
  bool read_only = false;  // write requests (set, mr, dr, log start/stop) are refused
};

// A token file: one token per line, "read-only <token>" for a read-only one, '#' comments.
// Refused: a missing or unreadable file, a file others may read (chmod 600), no token, a token
// shorter than 16 characters or with spaces. Errors name file:line.
std::vector<Token> read_token_file(const std::string& path);
// Tokens from `file` if given, else the STRIDE_TOKEN variable (a full token), else none.
std::vector<Token> tokens_from(const std::string& file);

std::string random_nonce();  // kNonceBytes from the OS's generator
// HMAC-SHA256 of `message` under `key` (32 bytes), the keyed hash of both proofs.
std::string keyed_hash(std::string_view key, std::string_view message);
std::string client_proof(std::string_view token, std::string_view server_nonce,
                         std::string_view client_nonce);
std::string server_proof(std::string_view token, std::string_view server_nonce,
                         std::string_view client_nonce);
bool same_proof(std::string_view a, std::string_view b);  // constant time

}  // namespace stride::debug
