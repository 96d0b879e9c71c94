
### resonance

resonance-axis-ratio = razão de frequências r = ω/ωₙ
resonance-axis-amplification = amplificação |H| = X/(F₀/k)
resonance-axis-magnitude-db = magnitude 20·log₁₀|H|
resonance-axis-phase = fase ∠H (atraso de x em relação a F)
resonance-plot-magnitude-db = Amplificação |H(r)| em dB
resonance-family = família ζ = { $from } … { $to }
resonance-current = ζ atual = { $zeta }
resonance-drive = excitação r = { $ratio }
resonance-peak = pico
resonance-quadrature = −90° em r = 1
resonance-legend-width = largura de meia potência r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 até r = { $upper }
resonance-legend-cutoff = corte de −3 dB em r = { $upper }
resonance-band-width = pontos de meia potência (|H| = |H|max/√2) em r = { $lower } e { $upper }: largura do pico r₂ − r₁ = { $width }
resonance-band-broad = |H| fica acima de |H|max/√2 de r = 0 até r = { $upper }: o pico não tem ponto inferior de meia potência, portanto sua largura de meia potência é indefinida
resonance-band-cutoff = |H| cai para 1/√2 do seu valor estático (−3 dB) no corte r = { $upper }; sem pico não há largura de meia potência
resonance-peak-at = pico de ressonância { $gain } em r = { $ratio }
resonance-no-peak = sem pico de ressonância (ζ ≥ 1/√2): |H| apenas decresce a partir de 1 em r = 0
resonance-describe-magnitude = { $view ->
        [db] Magnitude em dB para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
       *[linear] Magnitude para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
    }
resonance-describe-phase = Atraso de fase do deslocamento em relação à força para ζ = { $zeta }: 0° em baixa frequência, −90° em r = 1 para qualquer razão de amortecimento, tendendo a −180° acima da ressonância; quanto menor ζ, mais brusca a transição. Na excitação r = { $drive }, o atraso é { $degrees } ({ $radians } rad).
resonance-envelope = envoltória ±E(t)
resonance-steady-amplitude = amplitude em regime permanente ±X
resonance-describe-time-growing = Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: não há regime permanente; a amplitude cresce e chega a { $largest }.
resonance-describe-time = { $case ->
        [beats] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: os movimentos livre e forçado batem com período { $period } (constante de tempo do decaimento { $tau }), tendendo à amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
        [build-up] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: na ressonância a amplitude cresce em direção à amplitude em regime permanente { $amplitude } com constante de tempo 1/(ζωₙ) = { $tau }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
       *[transient] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: após um transitório (constante de tempo { $tau }) ela se acomoda na amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
    }
resonance-fixed-base = base fixa
resonance-schematic = Massa sobre mola e amortecedor acima de uma base fixa, empurrada pela força F(t) = { $force } (seta acima da massa) em t = { $time }: deslocada { $displacement } do repouso.
resonance-beats-visible = visíveis
resonance-beats-no-free-oscillation = nenhum (sem oscilação livre, ζ ≥ 1)
resonance-beats-no-drive = nenhum (força constante)
resonance-beats-same-frequency = nenhum (excitação em ω_d)
resonance-beats-too-fast = nenhum (tão rápido quanto a oscilação)
resonance-beats-dies-out = nenhum (o movimento livre se extingue antes)
resonance-title = Ressonância forçada
resonance-summary = Uma massa de 1 kg sobre uma mola (k = ωₙ²·m) e um amortecedor (c = 2ζωₙ·m), em repouso, é excitada a partir de t = 0 por F(t) = F₀·cos(ωt). Em regime permanente, ela se move na frequência de excitação com amplitude |H(r)|·F₀/k, atrasada em relação à força pela fase de H, onde r = ω/ωₙ. Um amortecimento leve produz um pico alto e estreito perto de r = 1 (altura ≈ Q = 1/(2ζ)). Sua largura de meia potência, r₂ − r₁ entre as duas razões de frequência em que |H| = |H|max/√2, é ≈ 2ζ para amortecimento leve; acima de ζ ≈ 0,383 o ponto inferior chega a r = 0 e a largura fica indefinida, e acima de ζ = 1/√2 não há pico algum. Excitada exatamente na ressonância, a amplitude cresce ao longo de algumas constantes de tempo 1/(ζωₙ) sem batimento; excitada perto dela, os movimentos livre e forçado batem entre si até que a parte livre se extinga.
resonance-param-zeta = razão de amortecimento
resonance-param-r = razão de excitação ω/ωₙ
resonance-param-wn = frequência natural
resonance-param-F0 = amplitude da força
resonance-param-view = escala da magnitude
resonance-param-view-linear = |H| linear
resonance-param-view-db = decibéis 20·log₁₀|H|
resonance-readout-peak-gain = pico de ressonância |H|max
resonance-readout-peak-ratio = pico em r = ω/ωₙ
resonance-readout-Q = fator de qualidade Q = 1/(2ζ)
resonance-readout-peak-width = largura de meia potência do pico de |H| r₂ − r₁ (ζ < 0,383)
resonance-readout-gain-at-r = ganho |H(r)| na excitação
resonance-readout-phase-at-r = fase ∠H(r) na excitação
resonance-readout-amplitude = amplitude em regime permanente X = |H|·F₀/k
resonance-readout-beat-period = período de batimento 2π/|ω − ω_d| (enquanto há batimento)
resonance-readout-beats = batimentos em x(t)
resonance-plot-magnitude = Amplificação |H(r)|
resonance-plot-phase = Fase ∠H(r)
resonance-plot-time = Resposta a partir do repouso x(t)
resonance-preset-1 = Na ressonância, ζ = 0,05
resonance-preset-2 = Batimento perto da ressonância, r = 0,9
resonance-preset-3 = Sem pico, ζ ≈ 1/√2
resonance-preset-4 = Quase estático, r = 0,2
resonance-preset-5 = Isolamento, r = 3

### flutter

flutter-no-oscillation = sem oscilação
flutter-series-h-section = seção em H de 1940 (aprox. didática)
flutter-series-box = caixão aerodinâmico (aprox. didática)
flutter-series-simplest = A₂* equivalente ao modelo mais simples
flutter-series-simplest-line = modelo mais simples ζ_s − g·U
flutter-axis-reduced-velocity = velocidade reduzida U/(f·B) = 2π/K
flutter-axis-wind-speed = velocidade do vento U
flutter-axis-effective-damping = razão de amortecimento efetiva ζ_eff
flutter-axis-twist = torção θ
flutter-threshold = limiar 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = polo superior
flutter-lower-pole = polo inferior
flutter-amplitude = amplitude ±a(t)
flutter-limit-cycle = ciclo limite ±{ $amplitude }
flutter-describe-derivative = A₂* em função da velocidade reduzida para { $model ->
        [h] a seção em H de 1940
        [box] o caixão aerodinâmico
       *[simplest] o modelo mais simples
    } (aproximação didática, não valores medidos): a torção cresce onde A₂* ultrapassa 4Iζ_s/(ρB⁴).
flutter-describe-derivative-now = { $description } Com U = { $speed } (K = { $k }, U/(fB) = { $reduced_velocity }), A₂* = { $a2 }, { $side ->
        [above] acima do
       *[below] abaixo do
    } limiar { $threshold }.
flutter-describe-damping = Razão de amortecimento efetiva { $model ->
        [h] da seção em H de 1940
        [box] do caixão aerodinâmico
       *[simplest] do modelo mais simples
    }, a partir de ζ_s = { $zeta_s } com ar parado; { $crossing ->
        [inside] ela se anula na velocidade crítica { $speed }
        [beyond] ela só se anularia em { $speed }, além do máximo traçado, { $limit }
       *[never] ela nunca se anula até 100 m/s: o vento só acrescenta amortecimento
    }.
flutter-describe-damping-now = { $description } Com U = { $speed }, ela vale { $zeta }, { $sign ->
        [positive] positiva (estável)
        [negative] negativa (flutter)
       *[zero] zero
    }.
flutter-describe-damping-still = { $description } Com este vento, o tabuleiro não oscila.
flutter-describe-locus = Par de polos à medida que o vento aumenta: { $re_calm } ± { $im_calm }i 1/s com ar parado, { $re_end } ± { $im_end }i 1/s a { $limit }, { $crosses ->
        [yes] cruzando o eixo imaginário em U_crit
       *[no] sem nunca cruzar o eixo imaginário
    }.
flutter-describe-locus-now = { $description } Com U = { $speed }, os polos são { $re } ± { $im }i 1/s, no semiplano { $side ->
        [right] direito (instável)
       *[left] esquerdo (estável)
    }.
flutter-oscillation = a oscilação
flutter-oscillation-at = a oscilação de { $frequency } Hz
flutter-describe-response = { $regime }: a partir de uma torção inicial de { $twist }, { $oscillation } { $case ->
        [settling] cresce até { $end } no fim do gráfico ({ $window }), estabilizando-se perto do ciclo limite de { $limit } (90 % dele após { $time })
        [slow] cresce apenas até { $end } no fim do gráfico ({ $window }); levaria { $time } para atingir 90 % do ciclo limite de { $limit }
        [settled] estabiliza-se no ciclo limite de { $limit } até o fim do gráfico ({ $window })
        [grows] cresce até { $end } no fim do gráfico ({ $window })
       *[dies] diminui até { $end } no fim do gráfico ({ $window })
    }.
flutter-describe-response-torn = { $description } Uma torção tão grande teria destruído qualquer tabuleiro muito antes; o limite é apenas uma hipótese didática.
flutter-schematic-title = Seção transversal do tabuleiro
flutter-drawn-clipped = desenhado cortado em { $angle }
flutter-drawn-true-scale = desenhado em escala real
flutter-drawn-larger = desenhado { $factor } vezes maior
flutter-drawn-note = ({ $drawn })
flutter-schematic = Seção transversal do tabuleiro da ponte em t = { $time }: torcida { $twist } ({ $drawn }), vento de { $wind } vindo da esquerda.
flutter-wind = vento U = { $speed }
flutter-title = Flutter: a ponte de Tacoma Narrows
flutter-summary = Um vento constante pode fornecer energia a um tabuleiro de ponte em torção por meio do seu próprio movimento. Scanlan escreveu o momento do vento sobre um tabuleiro em torção com derivadas de flutter medidas em túneis de vento: A₂* multiplica a velocidade de torção (um termo de amortecimento) e A₃* a torção (um termo de rigidez), ambas funções da frequência reduzida K = Bω/U. A razão de amortecimento do tabuleiro passa a ser ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I): para a seção em H, pouco aerodinâmica, do tabuleiro de Tacoma de 1940, A₂* muda de sinal à medida que o vento aumenta, e assim que ultrapassa o limiar 4Iζ_s/(ρB⁴) qualquer pequena torção cresce na frequência de torção própria do tabuleiro (perto de 0,2 Hz) — flutter (drapejamento), não ressonância: um vento constante não tem frequência a ser sintonizada, o próprio movimento gera sua excitação. A frequência é obtida por iteração em cada velocidade do vento, já que K depende dela. A teoria linear deixa a torção crescer indefinidamente; aqui se supõe que o termo de amortecimento do vento cai à metade com uma torção θ_s, o que limita o movimento a um grande ciclo limite, como em 7 de novembro de 1940, quando, com ventos de cerca de 42 mph, a torção cresceu em menos de uma hora até o tabuleiro se romper. Aproximações didáticas, declaradas como tais: A₂* e A₃* são curvas suaves com a forma dos resultados publicados para a seção em H e para seções semelhantes a aerofólios (Scanlan e Tomko 1971; Billah e Scanlan 1991), e não valores lidos deles; I, ζ_s e θ_s são supostos. Um caixão aerodinâmico, cujo A₂* permanece negativo, nunca entra em flutter nessa faixa. O modelo mais simples ζ_eff = ζ_s − g·U é mantido para comparação.
flutter-param-U = velocidade do vento
flutter-param-model = modelo do momento do vento
flutter-param-model-scanlan = derivadas de flutter (Scanlan)
flutter-param-model-linear = modelo mais simples: ζ_eff = ζ_s − g·U
flutter-param-section = seção transversal do tabuleiro
flutter-param-section-h = seção em H de 1940 (vigas de alma cheia)
flutter-param-section-box = viga-caixão aerodinâmica
flutter-param-B = largura do tabuleiro
flutter-param-I = momento de inércia de massa por unidade de comprimento (suposto para 1940)
flutter-param-f0 = frequência de torção com ar parado
flutter-param-zeta-s = razão de amortecimento estrutural (suposta para 1940)
flutter-param-theta0 = torção inicial
flutter-param-theta-s = torção na qual o amortecimento do vento cai à metade (hipótese didática)
flutter-param-slope = modelo mais simples: amortecimento perdido por m/s
flutter-readout-regime = regime de uma pequena torção
flutter-readout-U-crit = velocidade crítica (de flutter) U_crit, buscada até 100 m/s
flutter-readout-zeta-eff = razão de amortecimento efetiva ζ_eff de uma pequena torção
flutter-readout-growth-rate = taxa de crescimento σ de uma pequena torção (< 0: decai)
flutter-readout-doubling-time = uma pequena torção dobra a cada
flutter-readout-frequency = frequência de torção no vento f
flutter-readout-K = frequência reduzida K = Bω/U
flutter-readout-reduced-velocity = velocidade reduzida U/(f·B) = 2π/K
flutter-readout-A2 = derivada de flutter A₂*(K)
flutter-readout-A3 = derivada de flutter A₃*(K)
flutter-readout-limit-deg = amplitude de torção do ciclo limite (com o limite suposto θ_s)
flutter-readout-time-to-large = tempo de θ₀ até 90 % do ciclo limite
flutter-readout-amplitude-end-deg = amplitude de torção no fim do gráfico
flutter-plot-derivative = Derivada de flutter A₂* e limiar de flutter
flutter-plot-damping = Amortecimento efetivo em função da velocidade do vento
flutter-plot-locus = Lugar das raízes à medida que o vento aumenta
flutter-plot-response = Torção do tabuleiro θ(t) ao longo de minutos
flutter-preset-1 = Tacoma 1940, 10 m/s (estável)
flutter-preset-2 = Tacoma 1940, 19 m/s (dia do colapso, ≈ 42 mph)
flutter-preset-3 = Tacoma 1940, vendaval de 30 m/s
flutter-preset-4 = Tabuleiro em caixão aerodinâmico, 19 m/s
flutter-preset-5 = Tabuleiro em caixão aerodinâmico, 40 m/s
flutter-preset-6 = Modelo mais simples, 19 m/s (ζ_eff = ζ_s − g·U)
flutter-table-caption = Flutter não é ressonância
flutter-table-column-1 = caso
flutter-table-column-2 = o que o alimenta
flutter-table-column-3 = frequência
flutter-table-column-4 = amortecimento
flutter-table-column-5 = amplitude
flutter-table-column-6 = solução
flutter-table-resonance-1 = Ressonância forçada (para comparação)
flutter-table-resonance-2 = uma força externa oscilando perto de ωₙ (passos em marcha, um motor)
flutter-table-resonance-3 = imposta pela força; deve coincidir com ωₙ
flutter-table-resonance-4 = positivo: limita o pico a cerca de 1/(2ζ) × o valor estático
flutter-table-resonance-5 = regime permanente limitado
flutter-table-resonance-6 = dessintonizar ou acrescentar amortecimento
flutter-table-underdamped-1 = Vento abaixo de U_crit
flutter-table-underdamped-2 = vento constante; momento ∝ velocidade de torção (A₂*) e torção (A₃*)
flutter-table-underdamped-3 = a própria do tabuleiro, um pouco deslocada por A₃*
flutter-table-underdamped-4 = ζ_eff > 0: A₂* abaixo do limiar 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = uma torção se extingue
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = Em U_crit
flutter-table-undamped-2 = vento constante; momento ∝ velocidade de torção (A₂*) e torção (A₃*)
flutter-table-undamped-3 = a própria do tabuleiro
flutter-table-undamped-4 = ζ_eff = 0: polos sobre o eixo imaginário
flutter-table-undamped-5 = uma torção persiste inalterada
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = Flutter, vento acima de U_crit
flutter-table-negatively-damped-2 = vento constante; o próprio movimento gera sua excitação
flutter-table-negatively-damped-3 = a própria do tabuleiro, sem necessidade de sintonia
flutter-table-negatively-damped-4 = ζ_eff < 0: entra energia a cada ciclo
flutter-table-negatively-damped-5 = cresce até que o limite de amplitude (ou o tabuleiro) ceda
flutter-table-negatively-damped-6 = uma seção cujo A₂* permanece negativo: tabuleiro aerodinâmico, vazado ou enrijecido
