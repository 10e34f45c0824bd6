from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.equilibria_out import EquilibriaOut
from ...models.equilibria_request import EquilibriaRequest
from ...models.error_out import ErrorOut
from ...types import Response


def _get_kwargs(
    *,
    body: EquilibriaRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/equilibria",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> EquilibriaOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = EquilibriaOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[EquilibriaOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriaRequest,
) -> Response[EquilibriaOut | ErrorOut]:
    """Every equilibrium for a tip deflection (minima, saddles, maxima)

     All equilibria inside the physical range (`tensegrity_opt.find_equilibria`), sorted by energy;
    `morse_index`/`kind` classify each one. `method: homotopy` certifies the set (`certified`) for
    chains up to the server's `homotopy_max_segments` (default 5); the default search is complete in
    practice, not certified.

    Args:
        body (EquilibriaRequest): Every equilibrium (minima, saddles, maxima) for a tip
            deflection.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriaOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriaRequest,
) -> EquilibriaOut | ErrorOut | None:
    """Every equilibrium for a tip deflection (minima, saddles, maxima)

     All equilibria inside the physical range (`tensegrity_opt.find_equilibria`), sorted by energy;
    `morse_index`/`kind` classify each one. `method: homotopy` certifies the set (`certified`) for
    chains up to the server's `homotopy_max_segments` (default 5); the default search is complete in
    practice, not certified.

    Args:
        body (EquilibriaRequest): Every equilibrium (minima, saddles, maxima) for a tip
            deflection.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriaOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriaRequest,
) -> Response[EquilibriaOut | ErrorOut]:
    """Every equilibrium for a tip deflection (minima, saddles, maxima)

     All equilibria inside the physical range (`tensegrity_opt.find_equilibria`), sorted by energy;
    `morse_index`/`kind` classify each one. `method: homotopy` certifies the set (`certified`) for
    chains up to the server's `homotopy_max_segments` (default 5); the default search is complete in
    practice, not certified.

    Args:
        body (EquilibriaRequest): Every equilibrium (minima, saddles, maxima) for a tip
            deflection.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriaOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: EquilibriaRequest,
) -> EquilibriaOut | ErrorOut | None:
    """Every equilibrium for a tip deflection (minima, saddles, maxima)

     All equilibria inside the physical range (`tensegrity_opt.find_equilibria`), sorted by energy;
    `morse_index`/`kind` classify each one. `method: homotopy` certifies the set (`certified`) for
    chains up to the server's `homotopy_max_segments` (default 5); the default search is complete in
    practice, not certified.

    Args:
        body (EquilibriaRequest): Every equilibrium (minima, saddles, maxima) for a tip
            deflection.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriaOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
